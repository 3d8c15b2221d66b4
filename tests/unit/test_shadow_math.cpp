// algorithms/shadow_math: the shadow-map maths of lessons 02 and 03. Expected values worked out by hand
// in the comments.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <random>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/shadow_math.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::shadow;

namespace {
bool near3(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(eps)));
}
}  // namespace

TEST_CASE("shadow_math: the texture matrix maps the light frustum onto [0,1]^3") {
  // Light at (0, 10, 0) looking down, 90-degree spot, near 1, far 21. The point straight below at
  // y = 0 is at distance 10: u = v = 0.5; depth: NDC z = (f+n)/(f-n) - 2fn/((f-n) d) = 22/20 - 42/200
  // = 0.89, window depth 0.945.
  const glm::mat4 V = glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::mat4 P = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 21.0f);
  const glm::mat4 T = textureMatrix(P, V);
  CHECK(near3(shadowCoord(T, {0, 0, 0}), {0.5f, 0.5f, 0.945f}));
  // On the near plane's centre: depth 0; a point 10 to the side at distance 10 is on the 45-degree edge.
  CHECK(shadowCoord(T, {0, 9, 0}).z == doctest::Approx(0.0f).epsilon(1e-5));
  const glm::vec3 edge = shadowCoord(T, {10, 0, 0});
  CHECK((std::abs(edge.x - 1.0f) < 1e-4f || std::abs(edge.x) < 1e-4f || std::abs(edge.y - 1.0f) < 1e-4f ||
         std::abs(edge.y) < 1e-4f));
}

TEST_CASE("shadow_math: depth comparison is LEQUAL after the bias") {
  CHECK(depthCompare(0.5f, 0.5f, 0.0f) == 1.0f);    // equal: lit (LEQUAL)
  CHECK(depthCompare(0.51f, 0.5f, 0.0f) == 0.0f);   // behind the occluder: shadowed
  CHECK(depthCompare(0.51f, 0.5f, 0.02f) == 1.0f);  // the bias rescues it
  CHECK(depthCompare(0.2f, 0.5f, 0.0f) == 1.0f);
}

TEST_CASE("shadow_math: a hand-made 2x2 depth map, nearest lookup") {
  // Row 0 (v < 0.5): 0.3 0.9; row 1 (v >= 0.5): 0.9 0.9.
  const DepthMap m(2, 2, {0.3f, 0.9f, 0.9f, 0.9f});
  CHECK(shadowLookup(m, {0.25f, 0.25f, 0.5f}, 0.0f) == 0.0f);  // texel (0,0) = 0.3 < 0.5
  CHECK(shadowLookup(m, {0.75f, 0.25f, 0.5f}, 0.0f) == 1.0f);  // texel (1,0) = 0.9
  CHECK(shadowLookup(m, {0.25f, 0.75f, 0.5f}, 0.0f) == 1.0f);  // texel (0,1)
  CHECK(shadowLookup(m, {1.5f, 0.25f, 0.99f}, 0.0f) == 1.0f);  // outside: lit
  CHECK(shadowLookup(m, {0.25f, 0.25f, 1.5f}, 0.0f) == 1.0f);  // beyond the far plane: lit
  CHECK(shadowLookup(m, {0.25f, 0.25f, 0.31f}, 0.02f) == 1.0f);
  CHECK_THROWS_AS(DepthMap(2, 2, std::vector<float>{1, 2, 3}), std::invalid_argument);
  CHECK_THROWS_AS(DepthMap(0, 2, 1.0f), std::invalid_argument);
}

TEST_CASE("shadow_math: slope-scaled bias") {
  CHECK(slopeScaledBias(0.001f, 0.01f, 1.0f, 1.0f) == doctest::Approx(0.001f));  // head-on: tan 0 = 0
  // 45 degrees: tan = 1 -> 0.001 + 0.01.
  CHECK(slopeScaledBias(0.001f, 0.01f, std::sqrt(0.5f), 1.0f) == doctest::Approx(0.011f));
  // 60 degrees: tan = sqrt 3 -> 0.001 + 0.01732 = 0.01832, clamped to 0.015.
  CHECK(slopeScaledBias(0.001f, 0.01f, 0.5f, 0.015f) == doctest::Approx(0.015f));
  CHECK(slopeScaledBias(0.001f, 0.01f, 0.0f, 0.05f) == doctest::Approx(0.05f));
  CHECK(slopeScaledBias(0.001f, 0.01f, -0.5f, 0.05f) == doctest::Approx(0.05f));
}

TEST_CASE("shadow_math: bilinear PCF weights") {
  // At a texel centre (1.5, 2.5) the whole weight is on texel (1, 2): x0 = 1, fraction 0.
  CHECK(near3(glm::vec3(bilinearPcfWeights({1.5f, 2.5f})), {1, 0, 0}));
  // Halfway between four centres (2, 3): 0.25 each.
  const glm::vec4 w = bilinearPcfWeights({2.0f, 3.0f});
  for (int i = 0; i < 4; ++i) CHECK(w[i] == doctest::Approx(0.25f));
  // (1.75, 2.5): x0 = 1, fx = 0.25, fy = 0 -> 0.75, 0.25, 0, 0.
  const glm::vec4 w2 = bilinearPcfWeights({1.75f, 2.5f});
  CHECK(w2[0] == doctest::Approx(0.75f));
  CHECK(w2[1] == doctest::Approx(0.25f));
  CHECK(w2[2] == doctest::Approx(0.0f));
  // On the hand-made map, between the shadowed texel (0,0) and three lit ones: 3/4 lit.
  const DepthMap m(2, 2, {0.3f, 0.9f, 0.9f, 0.9f});
  CHECK(bilinearPcfLookup(m, {0.5f, 0.5f, 0.5f}, 0.0f) == doctest::Approx(0.75f));
  // 3x3 box around texel (0,0) with clamping: taps (-1..1)^2 clamp to texels 0/1; the texel (0,0)
  // is hit by (x,y) in {-1,0}^2: 4 of 9 shadowed -> 5/9 lit.
  CHECK(boxPcfLookup(m, {0.25f, 0.25f, 0.5f}, 0.0f, 3) == doctest::Approx(5.0f / 9.0f));
  CHECK(boxPcfLookup(m, {0.25f, 0.25f, 0.5f}, 0.0f, 1) == doctest::Approx(0.0f));
  CHECK_THROWS_AS(boxPcfLookup(m, {0.25f, 0.25f, 0.5f}, 0.0f, 2), std::invalid_argument);
}

TEST_CASE("shadow_math: cube face selection and face coordinates follow GL's table") {
  CHECK(cubeFace({1, 0.2f, -0.3f}) == 0);
  CHECK(cubeFace({-1, 0.2f, -0.3f}) == 1);
  CHECK(cubeFace({0.1f, 2, 0}) == 2);
  CHECK(cubeFace({0.1f, -2, 0}) == 3);
  CHECK(cubeFace({0.1f, 0.5f, 3}) == 4);
  CHECK(cubeFace({0.1f, 0.5f, -3}) == 5);
  CHECK(cubeFace({1, 1, 0}) == 0);  // ties: x first
  CHECK(cubeFace({0, 0, 0}) == -1);
  // +X with (1, 0.5, -0.5): sc = -rz = 0.5, tc = -ry = -0.5 -> s = 0.75, t = 0.25.
  const glm::vec2 uv = cubeFaceUv({1, 0.5f, -0.5f});
  CHECK(uv.x == doctest::Approx(0.75f));
  CHECK(uv.y == doctest::Approx(0.25f));
}

TEST_CASE("shadow_math: rendering a face with cubeFaceView lands where a cube lookup reads") {
  std::mt19937_64 rng(test::seedFor("cube views"));
  std::normal_distribution<float> n;
  const glm::mat4 P = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 50.0f);
  const glm::vec3 light(1, 2, 3);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 d = glm::normalize(glm::vec3(n(rng), n(rng), n(rng))) * 5.0f;
    const int face = cubeFace(d);
    const glm::vec4 clip = P * cubeFaceView(light, face) * glm::vec4(light + d, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    INFO("seed ", test::seed(), " case ", i, " face ", face);
    const glm::vec2 uv = cubeFaceUv(d);
    CHECK(0.5f * ndc.x + 0.5f == doctest::Approx(uv.x).epsilon(1e-3));
    CHECK(0.5f * ndc.y + 0.5f == doctest::Approx(uv.y).epsilon(1e-3));
    const float major = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    CHECK(0.5f * ndc.z + 0.5f == doctest::Approx(cubeDepth(major, 0.1f, 50.0f)).epsilon(1e-4));
  }
  CHECK_THROWS_AS(cubeFaceView(light, 6), std::invalid_argument);
}

TEST_CASE("shadow_math: volumes from a box and a frustum, their overlap and intersection") {
  const ConvexVolume box = volumeFromBox({{-1, -1, -1}, {1, 1, 1}});
  for (const glm::vec4& p : box.planes) CHECK(glm::dot(glm::vec3(p), glm::vec3(0)) + p.w == doctest::Approx(1.0f));
  // A camera at z = 10 looking down -z, near 1, far 100: sees the box.
  const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 1.0f, 100.0f) *
                       glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0), glm::vec3(0, 1, 0));
  const ConvexVolume frustum = volumeFromViewProj(vp);
  CHECK(volumesMayIntersect(box, frustum));
  // Every inward plane has the camera's target point inside.
  for (const glm::vec4& p : frustum.planes) CHECK(glm::dot(glm::vec3(p), glm::vec3(0)) + p.w > 0.0f);
  // The box lies entirely inside: the intersection's points are its 8 corners (each found on 3 faces).
  const auto pts = intersectionPoints(box, frustum);
  CHECK(pts.size() == 24);
  for (const glm::vec3& q : pts) CHECK(glm::all(glm::lessThanEqual(glm::abs(q), glm::vec3(1.0001f))));
  // A box behind the camera misses.
  const ConvexVolume behind = volumeFromBox({{-1, -1, 20}, {1, 1, 22}});
  CHECK_FALSE(volumesMayIntersect(behind, frustum));
  CHECK(intersectionPoints(behind, frustum).empty());
  // A big ground box cut by the frustum: every point inside both (within a tolerance).
  const ConvexVolume ground = volumeFromBox({{-50, -1, -50}, {50, 0, 50}});
  const auto cut = intersectionPoints(ground, frustum);
  CHECK(!cut.empty());
  for (const glm::vec3& q : cut) {
    for (const glm::vec4& p : frustum.planes) CHECK(glm::dot(glm::vec3(p), q) + p.w > -1e-2f);
    CHECK(q.y <= 1e-3f);
  }
  CHECK_THROWS_AS(volumeFromViewProj(glm::mat4(0.0f)), std::invalid_argument);
  CHECK_THROWS_AS(volumeFromBox(Aabb{}), std::invalid_argument);
}

TEST_CASE("shadow_math: caster culling against the swept light volume") {
  // The view: the box [-1,1]^3 as a volume. Light travels straight down (0,-1,0).
  const ConvexVolume view = volumeFromBox({{-1, -1, -1}, {1, 1, 1}});
  const glm::vec3 down(0, -1, 0);
  // Above the view: its shadow falls into it -> kept.
  CHECK(casterMayShadow({{-0.5f, 5, -0.5f}, {0.5f, 6, 0.5f}}, view, down));
  // Below the view: light travels away from the view -> culled.
  CHECK_FALSE(casterMayShadow({{-0.5f, -6, -0.5f}, {0.5f, -5, 0.5f}}, view, down));
  // Above but off to the side: the sweep never enters -> culled.
  CHECK_FALSE(casterMayShadow({{3, 5, -0.5f}, {4, 6, 0.5f}}, view, down));
  // The same caster with a slanted light (1, -1, 0) travelling toward -x... it moves +x: culled;
  // with (-1,-1,0) it moves toward the view: the x planes cannot separate it -> kept.
  CHECK_FALSE(casterMayShadow({{3, 5, -0.5f}, {4, 6, 0.5f}}, view, glm::normalize(glm::vec3(1, -1, 0))));
  CHECK(casterMayShadow({{3, 5, -0.5f}, {4, 6, 0.5f}}, view, glm::normalize(glm::vec3(-1, -1, 0))));
  // Inside: kept.
  CHECK(casterMayShadow({{-0.1f, -0.1f, -0.1f}, {0.1f, 0.1f, 0.1f}}, view, down));
}

TEST_CASE("shadow_math: the orthographic fit covers the receivers and the casters toward the light") {
  // Light straight down: light view x = world x, y = world -z... use only extents.
  const std::vector<glm::vec3> receivers{{-2, 0, -3}, {4, 0, -3}, {-2, 0, 5}, {4, 0, 5}};
  const std::vector<Aabb> casters{{{0, 0, 0}, {1, 10, 1}}};
  const OrthoFit fit = fitOrthographic({0, -1, 0}, receivers, casters, 1024, false);
  const glm::mat4 m = fit.projection * fit.view;
  for (const glm::vec3& r : receivers) {
    const glm::vec4 c = m * glm::vec4(r, 1);
    CHECK(std::abs(c.x) <= 1.0001f);
    CHECK(std::abs(c.y) <= 1.0001f);
    CHECK(std::abs(c.z) < 1.0f);
  }
  // The caster's top (y = 10) is inside the depth range, nearer the light than the ground.
  const glm::vec4 top = m * glm::vec4(0.5f, 10, 0.5f, 1);
  const glm::vec4 ground = m * glm::vec4(0.5f, 0, 0.5f, 1);
  CHECK(top.z > -1.0f);
  CHECK(top.z < ground.z);
  // Extent 6 x 8 without snapping: the texel is 8 / 1024 across the larger side.
  CHECK(fit.texelWorld == doctest::Approx(8.0f / 1024.0f));
  CHECK_THROWS_AS(fitOrthographic({0, -1, 0}, {}, casters, 1024, false), std::invalid_argument);
  CHECK_THROWS_AS(fitOrthographic({0, 0, 0}, receivers, casters, 1024, false), std::invalid_argument);
  CHECK_THROWS_AS(fitOrthographic({0, -1, 0}, receivers, casters, 0, false), std::invalid_argument);
}

TEST_CASE("shadow_math: snapping keeps the texel grid fixed while the receivers slide") {
  // Light straight down, receivers 8 x 8: half size 4 * (1 + 2/1024) = 4.0078; its power of two
  // is 8, the step 8/4 = 2, so it rounds up to 6 and one texel is 12 / 1024.
  std::vector<glm::vec3> r{{-4, 0, -4}, {4, 0, -4}, {-4, 0, 4}, {4, 0, 4}};
  CHECK(fitOrthographic({0, -1, 0}, r, {}, 1024, true).texelWorld == doctest::Approx(12.0f / 1024.0f));
  // With a slanted light, sliding the receivers by fractions of a texel keeps the projection's
  // grid: the world origin maps to the same texel phase.
  const glm::vec3 dir = glm::normalize(glm::vec3(-0.3f, -1, -0.2f));
  const OrthoFit a = fitOrthographic(dir, r, {}, 1024, true);
  for (float shift : {0.0031f, 0.17f, 1.3f}) {
    std::vector<glm::vec3> moved = r;
    for (auto& p : moved) p.x += shift;
    const OrthoFit b = fitOrthographic(dir, moved, {}, 1024, true);
    CHECK(b.texelWorld == doctest::Approx(a.texelWorld));
    const glm::vec4 ca = a.projection * a.view * glm::vec4(0, 0, 0, 1);
    const glm::vec4 cb = b.projection * b.view * glm::vec4(0, 0, 0, 1);
    const float texA = (0.5f * ca.x + 0.5f) * 1024.0f, texB = (0.5f * cb.x + 0.5f) * 1024.0f;
    const float phase = std::abs((texA - texB) - std::round(texA - texB));
    CHECK(phase < 1e-2f);
  }
}

TEST_CASE("shadow_math: view culling in clip space (boxOutsideClip)") {
  // Eye at the origin looking down -z, 90 degrees vertical, square, near 1, far 100: the frustum
  // holds |x|, |y| <= -z for 1 <= -z <= 100.
  const glm::mat4 vp = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 100.0f);
  auto box = [](glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
  };
  CHECK_FALSE(boxOutsideClip(vp, box({-1, -1, -11}, {1, 1, -9})));            // in front, in view
  CHECK(boxOutsideClip(vp, box({20, -1, -11}, {22, 1, -9})));                 // right of x = -z
  CHECK(boxOutsideClip(vp, box({-1, -1, -300}, {1, 1, -200})));               // beyond the far plane
  CHECK(boxOutsideClip(vp, box({-1, -1, 0.5f}, {1, 1, 5})));                  // behind the eye (w < 0 corners)
  CHECK(boxOutsideClip(vp, box({-1, -1, -0.9f}, {1, 1, -0.5f})));             // between the eye and the near plane
  CHECK_FALSE(boxOutsideClip(vp, box({-1, -1, -5}, {1, 1, 5})));              // through the eye into the view
  CHECK_FALSE(boxOutsideClip(vp, box({-500, -500, -500}, {500, 500, 500})));  // around the whole frustum
  CHECK(boxOutsideClip(vp, Aabb{}));                                          // empty
  // Sound on random boxes: a box called outside has no point of a dense grid inside the frustum.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> at(-60.0f, 60.0f), size(0.1f, 30.0f);
  int outside = 0, inside = 0;
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 lo(at(rng), at(rng), at(rng) - 50.0f);
    const Aabb b = box(lo, lo + glm::vec3(size(rng), size(rng), size(rng)));
    bool seen = false;
    for (int i = 0; i <= 8 && !seen; ++i)
      for (int j = 0; j <= 8 && !seen; ++j)
        for (int k = 0; k <= 8 && !seen; ++k) {
          const glm::vec3 p = b.min + b.extent() * glm::vec3(i, j, k) / 8.0f;
          seen = -p.z >= 1.0f && -p.z <= 100.0f && std::abs(p.x) <= -p.z && std::abs(p.y) <= -p.z;
        }
    if (boxOutsideClip(vp, b)) {
      ++outside;
      CHECK_FALSE(seen);
    } else if (seen) {
      ++inside;
    }
  }
  CHECK(outside > 200);  // the test exercises both answers
  CHECK(inside > 200);
}

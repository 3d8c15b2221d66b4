// Graders for lesson 03 (make grade LESSON=03): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases check properties any correct answer has, or compare with
// the reference implementation (compiled into the course library). More cases, with seeds the
// grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "algorithms/shadow_math.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::kApprox;

TEST_CASE("ex03.1: slope-scaled bias by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  CHECK_NEAR(ex03::slopeScaledBias(0.002f, 0.01f, 1.0f, 1.0f), 0.002f, 1e-7);          // head-on: tan 0 = 0
  CHECK_NEAR(ex03::slopeScaledBias(0.0f, 0.01f, std::sqrt(0.5f), 1.0f), 0.01f, 1e-7);  // 45 degrees: tan = 1
  // 60 degrees: cos 0.5, tan = sqrt(0.75) / 0.5 = 1.7320508 -> 0.001 + 0.017320508.
  CHECK_NEAR(ex03::slopeScaledBias(0.001f, 0.01f, 0.5f, 1.0f), 0.018320508f, 1e-7);
  CHECK_NEAR(ex03::slopeScaledBias(0.001f, 0.01f, 0.5f, 0.01f), 0.01f, 1e-7);   // clamped
  CHECK_NEAR(ex03::slopeScaledBias(0.001f, 0.01f, 0.0f, 0.03f), 0.03f, 1e-7);   // grazing
  CHECK_NEAR(ex03::slopeScaledBias(0.001f, 0.01f, -0.7f, 0.03f), 0.03f, 1e-7);  // facing away
}

TEST_CASE("ex03.2: bilinear PCF weights by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // A texel centre (4.5, 7.5): t = (4, 7), f = 0: everything on texel (4, 7).
  CHECK_NEAR(ex03::bilinearPcfWeights({4.5f, 7.5f}), glm::vec4(1, 0, 0, 0), 1e-5);
  // (5.0, 8.0): t = (4.5, 7.5), f = (0.5, 0.5): a quarter each.
  CHECK_NEAR(ex03::bilinearPcfWeights({5.0f, 8.0f}), glm::vec4(0.25f), 1e-5);
  // (4.75, 7.9): t = (4.25, 7.4), f = (0.25, 0.4): 0.75*0.6, 0.25*0.6, 0.75*0.4, 0.25*0.4.
  CHECK_NEAR(ex03::bilinearPcfWeights({4.75f, 7.9f}), glm::vec4(0.45f, 0.15f, 0.30f, 0.10f), 1e-5);
  // Left of the first centre: t = -0.25 -> x0 = -1, fx = 0.75.
  CHECK_NEAR(ex03::bilinearPcfWeights({0.25f, 0.5f}), glm::vec4(0.25f, 0.75f, 0, 0), 1e-5);
}

TEST_CASE("ex03.2: random positions: weights in [0,1], summing to 1, reproducing the position") {
  std::mt19937_64 rng(test::seedFor("ex03.2"));
  std::uniform_real_distribution<float> u(0, 64);
  for (int i = 0; i < 200; ++i) {
    const glm::vec2 p(u(rng), u(rng));
    const glm::vec4 w = ex03::bilinearPcfWeights(p);
    INFO("random case ", i, " of 200 (seed ", test::seed(), ")");
    CAPTURE(p);
    CAPTURE(w);
    if (!CHECK_NEAR(w[0] + w[1] + w[2] + w[3], 1.0f, kApprox)) break;
    if (!CHECK_NEAR(glm::clamp(w, 0.0f, 1.0f), w, 1e-6)) break;  // every weight in [0, 1]
    // Interpolating the texel centres with the weights gives back p (bilinear reproduces linear functions).
    const glm::vec2 c0 = glm::floor(p - 0.5f) + 0.5f;
    const glm::vec2 q =
        w[0] * c0 + w[1] * (c0 + glm::vec2(1, 0)) + w[2] * (c0 + glm::vec2(0, 1)) + w[3] * (c0 + glm::vec2(1, 1));
    if (!CHECK_NEAR(q, p, grading::relativeTolerance(1e-4))) break;
  }
}

TEST_CASE("ex03.3: cube face of a direction" * SHADOWLAB_INDEPENDENT_CHECKS) {
  CHECK_EXACT(ex03::cubeFace({2, 1, -1}), 0);
  CHECK_EXACT(ex03::cubeFace({-2, 1, -1}), 1);
  CHECK_EXACT(ex03::cubeFace({0.5f, 3, -1}), 2);
  CHECK_EXACT(ex03::cubeFace({0.5f, -3, -1}), 3);
  CHECK_EXACT(ex03::cubeFace({0.5f, 0.2f, 0.9f}), 4);
  CHECK_EXACT(ex03::cubeFace({0.5f, 0.2f, -0.9f}), 5);
  CHECK_EXACT(ex03::cubeFace({1, -1, 0.5f}), 0);  // |x| = |y|: x wins
  CHECK_EXACT(ex03::cubeFace({0, -1, 1}), 3);     // |y| = |z|: y wins
  CHECK_EXACT(ex03::cubeFace({0, 0, 0}), -1);
}

TEST_CASE("ex03.3: random directions against the reference") {
  std::mt19937_64 rng(test::seedFor("ex03.3"));
  std::normal_distribution<float> n;
  for (int i = 0; i < 300; ++i) {
    const glm::vec3 d(n(rng), n(rng), n(rng));
    INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
    CAPTURE(d);
    if (!CHECK_EXACT(ex03::cubeFace(d), shadow::cubeFace(d))) break;
  }
}

TEST_CASE("ex03.4: caster culling against a box-shaped view, light straight down") {
  const shadow::ConvexVolume view = shadow::volumeFromBox({{-10, 0, -10}, {10, 5, 10}});
  const glm::vec3 down(0, -1, 0);
  INFO("view: the box (-10, 0, -10) to (10, 5, 10); light travels (0, -1, 0)");
  CHECK_EXACT(ex03::casterMayShadow({{-1, 20, -1}, {1, 30, 1}}, view, down), true);    // above: its shadow falls in
  CHECK_EXACT(ex03::casterMayShadow({{-1, 1, -1}, {1, 2, 1}}, view, down), true);      // inside
  CHECK_EXACT(ex03::casterMayShadow({{-1, -9, -1}, {1, -2, 1}}, view, down), false);   // below: light leaves
  CHECK_EXACT(ex03::casterMayShadow({{15, 20, -1}, {17, 30, 1}}, view, down), false);  // above, beside: never enters
  CHECK_EXACT(ex03::casterMayShadow({{9, 20, -1}, {17, 30, 1}}, view, down), true);    // overlaps the column above
}

TEST_CASE("ex03.4: slanted light: a caster beside the view shades it only when light travels toward it") {
  const shadow::ConvexVolume view = shadow::volumeFromBox({{-10, 0, -10}, {10, 5, 10}});
  const Aabb beside{{15, 10, -1}, {17, 12, 1}};  // x > 10, up high
  INFO("view: the box (-10, 0, -10) to (10, 5, 10); caster (15, 10, -1) to (17, 12, 1)");
  CHECK_EXACT(ex03::casterMayShadow(beside, view, glm::normalize(glm::vec3(-1, -1, 0))), true);  // toward -x: in
  CHECK_EXACT(ex03::casterMayShadow(beside, view, glm::normalize(glm::vec3(1, -1, 0))), false);  // away
  CHECK_EXACT(ex03::casterMayShadow(beside, view, glm::vec3(0, 0, -1)), false);  // along z: x plane keeps it out
}

TEST_CASE("ex03.4: random casters: never culled when a point of the swept box is inside") {
  std::mt19937_64 rng(test::seedFor("ex03.4"));
  std::uniform_real_distribution<float> u(-30, 30);
  const shadow::ConvexVolume view = shadow::volumeFromBox({{-5, -5, -5}, {5, 5, 5}});
  int kept = 0, culled = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::vec3 c(u(rng), u(rng), u(rng));
    const Aabb box{c - 1.0f, c + 1.0f};
    const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, -0.01f, 0));
    // Sample the sweep: the box centre and corners moved along dir.
    bool reaches = false;
    for (float s = 0; s < 120 && !reaches; s += 0.05f)
      for (int k = 0; k < 9 && !reaches; ++k) {
        const glm::vec3 p = (k == 8 ? c
                                    : glm::vec3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y,
                                                k & 4 ? box.max.z : box.min.z)) +
                            s * dir;
        reaches = glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(5.0f)));
      }
    const bool result = ex03::casterMayShadow(box, view, dir);
    INFO("random case ", i, " of 300 (seed ", test::seed(), "): view (-5,-5,-5) to (5,5,5)");
    CAPTURE(c);
    CAPTURE(dir);
    if (reaches && !CHECK_EXACT(result, true)) break;
    (result ? kept : culled)++;
  }
  INFO("kept ", kept, ", culled ", culled, " of 300 random boxes");
  CHECK_TRUE(culled > 50);  // and it does cull: most random boxes cannot reach a small view
}

TEST_CASE("ex03.5: the orthographic fit: light straight down over four receivers and a tower") {
  // Light straight down: lightViewAlong picks up = +x, so light x = world z... only extents matter:
  // the receivers span 6 m in x and 8 m in z, the tower reaches 10 m up.
  const std::vector<glm::vec3> receivers{{-2, 0, -3}, {4, 0, -3}, {-2, 0, 5}, {4, 0, 5}};
  const std::vector<Aabb> casters{{{0, 0, 0}, {1, 10, 1}}};
  const shadow::OrthoFit fit = ex03::fitOrthographic({0, -1, 0}, receivers, casters, 1024, false);
  const glm::mat4 m = fit.projection * fit.view;
  CAPTURE(fit.view);
  CAPTURE(fit.projection);
  glm::vec2 lo(1), hi(-1);
  for (const glm::vec3& r : receivers) {
    const glm::vec4 c = m * glm::vec4(r, 1);
    lo = glm::min(lo, glm::vec2(c)), hi = glm::max(hi, glm::vec2(c));
    INFO("receiver ", grading::show(r), " at clip ", grading::show(c));
    CHECK(std::abs(c.z) < 1.0f);
  }
  // Tight: the receivers touch every side of the map.
  CHECK_NEAR(lo, glm::vec2(-1), 1e-3);
  CHECK_NEAR(hi, glm::vec2(1), 1e-3);
  // The tower's top is in the depth range and nearer the light than the ground under it.
  const glm::vec4 top = m * glm::vec4(0.5f, 10, 0.5f, 1), ground = m * glm::vec4(0.5f, 0, 0.5f, 1);
  CAPTURE(top);
  CAPTURE(ground);
  CHECK(top.z > -1.0f);
  CHECK(top.z < ground.z);
  // One texel: the larger extent (8 m) over 1024.
  CHECK_NEAR(fit.texelWorld, 8.0f / 1024.0f, kApprox);
}

TEST_CASE("ex03.5: random slanted lights: receivers inside and tight, casters inside in depth") {
  std::mt19937_64 rng(test::seedFor("ex03.5"));
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < 30; ++i) {
    const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), -1.2f + 0.5f * u(rng), u(rng)));
    std::vector<glm::vec3> receivers;
    for (int k = 0; k < 12; ++k) receivers.push_back({20 * u(rng), 2 * u(rng), 20 * u(rng)});
    const glm::vec3 c(10 * u(rng), 15, 10 * u(rng));
    const std::vector<Aabb> casters{{c - 1.0f, c + 1.0f}};
    const shadow::OrthoFit fit = ex03::fitOrthographic(dir, receivers, casters, 2048, false);
    const glm::mat4 m = fit.projection * fit.view;
    INFO("random case ", i, " of 30 (seed ", test::seed(), "): 12 receivers in [-20, 20] x [-2, 2] x [-20, 20]");
    CAPTURE(dir);
    CAPTURE(c);
    glm::vec3 maxAbs(0);
    for (const glm::vec3& r : receivers) maxAbs = glm::max(maxAbs, glm::abs(glm::vec3(m * glm::vec4(r, 1))));
    // Every receiver inside the map and the depth range, and the map tight around them.
    INFO("largest |clip x, y, z| of the receivers: ", grading::show(maxAbs));
    if (!CHECK_TRUE(maxAbs.x <= 1.001f && maxAbs.y <= 1.001f && maxAbs.z <= 1.0f)) break;
    if (!CHECK_TRUE(maxAbs.x > 0.999f && maxAbs.y > 0.999f)) break;
    float nearest = 0;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner(k & 1 ? c.x + 1 : c.x - 1, k & 2 ? c.y + 1 : c.y - 1, k & 4 ? c.z + 1 : c.z - 1);
      nearest = std::min(nearest, (m * glm::vec4(corner, 1)).z);
    }
    INFO("the caster's corner nearest the light has clip z ", nearest, " (must be >= -1: not clipped)");
    if (!CHECK_TRUE(nearest >= -1.0f)) break;
  }
}

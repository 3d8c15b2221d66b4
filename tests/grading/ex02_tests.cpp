// Graders for lesson 02 (ctest -L ex02). Expected values are worked out by hand in the comments;
// the randomised cases compare against the formula written out independently here.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(eps)));
}
glm::vec3 project(const glm::mat4& T, const glm::vec3& p) {
  const glm::vec4 h = T * glm::vec4(p, 1.0f);
  return glm::vec3(h) / h.w;
}
}  // namespace

TEST_CASE("ex02.1: identity light camera: the texture matrix is the NDC remap") {
  // With P = V = I the world cube [-1,1]^3 is the light's NDC: (-1,-1,-1) -> 0, (1,1,1) -> 1,
  // (0.5, -0.5, 0) -> (0.75, 0.25, 0.5).
  const glm::mat4 T = ex02::shadowTextureMatrix(glm::mat4(1.0f), glm::mat4(1.0f));
  CHECK(near(project(T, {-1, -1, -1}), glm::vec3(0)));
  CHECK(near(project(T, {1, 1, 1}), glm::vec3(1)));
  CHECK(near(project(T, {0.5f, -0.5f, 0}), {0.75f, 0.25f, 0.5f}));
}

TEST_CASE("ex02.1: a spot light looking down from 10 m") {
  // V: eye (0,10,0) looking at the origin (up -z). P: 90 degrees, near 1, far 21. The origin is at
  // distance 10 on the axis: u = v = 0.5; NDC z = (f+n)/(f-n) - 2fn/((f-n) d) = 1.1 - 0.21 = 0.89,
  // depth 0.945. The point (10, 0, 0) is 45 degrees off the axis: on the edge of the map.
  const glm::mat4 V = glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::mat4 P = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 21.0f);
  const glm::mat4 T = ex02::shadowTextureMatrix(P, V);
  CHECK(near(project(T, {0, 0, 0}), {0.5f, 0.5f, 0.945f}));
  // V maps world +x to view +x: u = 1 at (10, 0, 0); depth again 0.945 (same view depth).
  CHECK(near(project(T, {10, 0, 0}), {1.0f, 0.5f, 0.945f}));
  // The near plane's centre has depth 0; the far plane's 1.
  CHECK(project(T, {0, 9, 0}).z == doctest::Approx(0.0f).epsilon(1e-4));
  CHECK(project(T, {0, -11, 0}).z == doctest::Approx(1.0f).epsilon(1e-4));
}

TEST_CASE("ex02.1: random light cameras: T = remap * P * V, with w kept") {
  std::mt19937_64 rng(test::seedFor("ex02.1"));
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 eye(u(rng) * 10, 5 + 5 * u(rng), u(rng) * 10);
    const glm::mat4 V = glm::lookAt(eye, glm::vec3(u(rng), 0, u(rng)), glm::vec3(0, 1, 0));
    const glm::mat4 P = glm::perspective(0.6f + 0.4f * u(rng), 1.0f, 0.5f, 50.0f);
    const glm::vec3 p(u(rng) * 3, u(rng), u(rng) * 3);
    const glm::vec4 clip = P * V * glm::vec4(p, 1);
    const glm::vec4 expected(0.5f * (clip.x + clip.w), 0.5f * (clip.y + clip.w), 0.5f * (clip.z + clip.w), clip.w);
    const glm::vec4 got = ex02::shadowTextureMatrix(P, V) * glm::vec4(p, 1);
    INFO("seed ", test::seed(), " case ", i);
    CHECK(glm::length(got - expected) < 1e-3f * std::max(1.0f, glm::length(expected)));
  }
}

TEST_CASE("ex02.2: the depth comparison, LEQUAL after the bias") {
  CHECK(ex02::depthCompare(0.4f, 0.6f, 0.0f) == 1.0f);     // in front of what the light saw: lit
  CHECK(ex02::depthCompare(0.6f, 0.4f, 0.0f) == 0.0f);     // behind it: shadowed
  CHECK(ex02::depthCompare(0.5f, 0.5f, 0.0f) == 1.0f);     // equal: LEQUAL says lit
  CHECK(ex02::depthCompare(0.505f, 0.5f, 0.01f) == 1.0f);  // acne removed by the bias
  CHECK(ex02::depthCompare(0.52f, 0.5f, 0.01f) == 0.0f);   // a real occluder still shadows
}

TEST_CASE("ex02.3: a hand-made 4x2 map: each texel, the edges and outside") {
  // Row 0 (v in [0, 0.5)):  0.2 0.8 0.8 0.8
  // Row 1 (v in [0.5, 1]): 0.8 0.8 0.3 0.8
  const shadow::DepthMap m(4, 2, {0.2f, 0.8f, 0.8f, 0.8f, 0.8f, 0.8f, 0.3f, 0.8f});
  CHECK(ex02::shadowLookup(m, {0.1f, 0.2f, 0.5f}, 0.0f) == 0.0f);    // texel (0,0) = 0.2 < 0.5
  CHECK(ex02::shadowLookup(m, {0.3f, 0.2f, 0.5f}, 0.0f) == 1.0f);    // texel (1,0) = 0.8
  CHECK(ex02::shadowLookup(m, {0.6f, 0.7f, 0.5f}, 0.0f) == 0.0f);    // texel (2,1) = 0.3: row 1 is v >= 0.5
  CHECK(ex02::shadowLookup(m, {0.6f, 0.2f, 0.5f}, 0.0f) == 1.0f);    // texel (2,0) = 0.8: rows not swapped
  CHECK(ex02::shadowLookup(m, {0.1f, 0.7f, 0.5f}, 0.0f) == 1.0f);    // texel (0,1) = 0.8: columns not swapped
  CHECK(ex02::shadowLookup(m, {0.1f, 0.2f, 0.21f}, 0.02f) == 1.0f);  // the bias applies
  CHECK(ex02::shadowLookup(m, {1.0f, 1.0f, 0.5f}, 0.0f) == 1.0f);    // u = v = 1: clamped to texel (3,1) = 0.8
}

TEST_CASE("ex02.3: outside the map or beyond the far plane the light saw nothing: lit") {
  const shadow::DepthMap m(2, 2, 0.1f);  // everything is shadowed inside
  CHECK(ex02::shadowLookup(m, {0.5f, 0.5f, 0.5f}, 0.0f) == 0.0f);
  CHECK(ex02::shadowLookup(m, {-0.1f, 0.5f, 0.5f}, 0.0f) == 1.0f);
  CHECK(ex02::shadowLookup(m, {0.5f, 1.2f, 0.5f}, 0.0f) == 1.0f);
  CHECK(ex02::shadowLookup(m, {0.5f, 0.5f, 1.5f}, 0.0f) == 1.0f);
}

TEST_CASE("ex02.3: random maps against the nearest-texel rule") {
  std::mt19937_64 rng(test::seedFor("ex02.3"));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 50; ++i) {
    const int w = 1 + int(u(rng) * 16), h = 1 + int(u(rng) * 16);
    std::vector<float> d(std::size_t(w * h));
    for (float& x : d) x = u(rng);
    const shadow::DepthMap m(w, h, d);
    for (int k = 0; k < 20; ++k) {
      const glm::vec3 uvz(u(rng) * 0.999f, u(rng) * 0.999f, u(rng));
      const int x = int(uvz.x * float(w)), y = int(uvz.y * float(h));
      const float expected = uvz.z - 0.01f <= d[std::size_t(y * w + x)] ? 1.0f : 0.0f;
      INFO("seed ", test::seed(), " map ", i, " lookup ", k);
      CHECK(ex02::shadowLookup(m, uvz, 0.01f) == expected);
    }
  }
}

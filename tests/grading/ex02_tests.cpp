// Graders for lesson 02 (make grade LESSON=02): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases compare with the reference implementation (compiled into
// the course library). More cases, with seeds the grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/shadow_math.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
glm::vec3 project(const glm::mat4& T, const glm::vec3& p) {
  const glm::vec4 h = T * glm::vec4(p, 1.0f);
  return glm::vec3(h) / h.w;
}
}  // namespace

TEST_CASE("ex02.1: identity light camera: the texture matrix is the NDC remap") {
  // With P = V = I the world cube [-1,1]^3 is the light's NDC: (-1,-1,-1) -> 0, (1,1,1) -> 1,
  // (0.5, -0.5, 0) -> (0.75, 0.25, 0.5).
  const glm::mat4 T = ex02::shadowTextureMatrix(glm::mat4(1.0f), glm::mat4(1.0f));
  CAPTURE(T);
  CHECK_NEAR(project(T, {-1, -1, -1}), glm::vec3(0), 1e-5);
  CHECK_NEAR(project(T, {1, 1, 1}), glm::vec3(1), 1e-5);
  CHECK_NEAR(project(T, {0.5f, -0.5f, 0}), glm::vec3(0.75f, 0.25f, 0.5f), 1e-5);
}

TEST_CASE("ex02.1: a spot light looking down from 10 m") {
  // V: eye (0,10,0) looking at the origin (up -z). P: 90 degrees, near 1, far 21. The origin is at
  // distance 10 on the axis: u = v = 0.5; NDC z = (f+n)/(f-n) - 2fn/((f-n) d) = 1.1 - 0.21 = 0.89,
  // depth 0.945. The point (10, 0, 0) is 45 degrees off the axis: on the edge of the map (V maps
  // world +x to view +x: u = 1), at the same depth. The near plane's centre has depth 0, the far's 1.
  const glm::mat4 V = glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::mat4 P = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 21.0f);
  const glm::mat4 T = ex02::shadowTextureMatrix(P, V);
  CAPTURE(T);
  CHECK_NEAR(project(T, {0, 0, 0}), glm::vec3(0.5f, 0.5f, 0.945f), 1e-4);
  CHECK_NEAR(project(T, {10, 0, 0}), glm::vec3(1.0f, 0.5f, 0.945f), 1e-4);
  CHECK_NEAR(project(T, {0, 9, 0}).z, 0.0f, 1e-4);
  CHECK_NEAR(project(T, {0, -11, 0}).z, 1.0f, 1e-4);
}

TEST_CASE("ex02.1: random light cameras against the reference, w kept") {
  std::mt19937_64 rng(test::seedFor("ex02.1"));
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 eye(u(rng) * 10, 5 + 5 * u(rng), u(rng) * 10);
    const glm::mat4 V = glm::lookAt(eye, glm::vec3(u(rng), 0, u(rng)), glm::vec3(0, 1, 0));
    const glm::mat4 P = glm::perspective(0.6f + 0.4f * u(rng), 1.0f, 0.5f, 50.0f);
    const glm::vec3 p(u(rng) * 3, u(rng), u(rng) * 3);
    INFO("random case ", i, " of 50 (seed ", test::seed(), ")");
    CAPTURE(P);
    CAPTURE(V);
    CAPTURE(p);
    if (!CHECK_NEAR(ex02::shadowTextureMatrix(P, V) * glm::vec4(p, 1), shadow::textureMatrix(P, V) * glm::vec4(p, 1),
                    grading::relativeTolerance(1e-3)))
      break;
  }
}

TEST_CASE("ex02.2: the depth comparison, LEQUAL after the bias") {
  CHECK_NEAR(ex02::depthCompare(0.6f, 0.4f, 0.0f), 0.0f, 0);     // behind what the light saw: shadowed
  CHECK_NEAR(ex02::depthCompare(0.4f, 0.6f, 0.0f), 1.0f, 0);     // in front of it: lit
  CHECK_NEAR(ex02::depthCompare(0.5f, 0.5f, 0.0f), 1.0f, 0);     // equal: LEQUAL says lit
  CHECK_NEAR(ex02::depthCompare(0.505f, 0.5f, 0.01f), 1.0f, 0);  // acne removed by the bias
  CHECK_NEAR(ex02::depthCompare(0.52f, 0.5f, 0.01f), 0.0f, 0);   // a real occluder still shadows
}

TEST_CASE("ex02.3: a hand-made 4x2 map: each texel, the edges and outside" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // Row 0 (v in [0, 0.5)):  0.2 0.8 0.8 0.8
  // Row 1 (v in [0.5, 1]): 0.8 0.8 0.3 0.8
  const shadow::DepthMap m(4, 2, {0.2f, 0.8f, 0.8f, 0.8f, 0.8f, 0.8f, 0.3f, 0.8f});
  CHECK_NEAR(ex02::shadowLookup(m, {0.1f, 0.2f, 0.5f}, 0.0f), 0.0f, 0);    // texel (0,0) = 0.2 < 0.5
  CHECK_NEAR(ex02::shadowLookup(m, {0.3f, 0.2f, 0.5f}, 0.0f), 1.0f, 0);    // texel (1,0) = 0.8
  CHECK_NEAR(ex02::shadowLookup(m, {0.6f, 0.7f, 0.5f}, 0.0f), 0.0f, 0);    // texel (2,1) = 0.3: row 1 is v >= 0.5
  CHECK_NEAR(ex02::shadowLookup(m, {0.6f, 0.2f, 0.5f}, 0.0f), 1.0f, 0);    // texel (2,0) = 0.8: rows not swapped
  CHECK_NEAR(ex02::shadowLookup(m, {0.1f, 0.7f, 0.5f}, 0.0f), 1.0f, 0);    // texel (0,1) = 0.8: columns not swapped
  CHECK_NEAR(ex02::shadowLookup(m, {0.1f, 0.2f, 0.21f}, 0.02f), 1.0f, 0);  // the bias applies
  CHECK_NEAR(ex02::shadowLookup(m, {1.0f, 1.0f, 0.5f}, 0.0f), 1.0f, 0);    // u = v = 1: clamped to texel (3,1) = 0.8
}

TEST_CASE("ex02.3: outside the map or beyond the far plane the light saw nothing: lit") {
  const shadow::DepthMap m(2, 2, 0.1f);  // everything is shadowed inside
  CHECK_NEAR(ex02::shadowLookup(m, {0.5f, 0.5f, 0.5f}, 0.0f), 0.0f, 0);
  CHECK_NEAR(ex02::shadowLookup(m, {-0.1f, 0.5f, 0.5f}, 0.0f), 1.0f, 0);
  CHECK_NEAR(ex02::shadowLookup(m, {0.5f, 1.2f, 0.5f}, 0.0f), 1.0f, 0);
  CHECK_NEAR(ex02::shadowLookup(m, {0.5f, 0.5f, 1.5f}, 0.0f), 1.0f, 0);
}

TEST_CASE("ex02.3: random maps against the reference") {
  std::mt19937_64 rng(test::seedFor("ex02.3"));
  std::uniform_real_distribution<float> u(0, 1);
  bool ok = true;
  for (int i = 0; i < 50 && ok; ++i) {
    const int w = 1 + int(u(rng) * 16), h = 1 + int(u(rng) * 16);
    std::vector<float> d(std::size_t(w * h));
    for (float& x : d) x = u(rng);
    const shadow::DepthMap m(w, h, d);
    for (int k = 0; k < 20 && ok; ++k) {
      const glm::vec3 uvz(u(rng) * 1.2f - 0.1f, u(rng) * 1.2f - 0.1f, u(rng) * 1.1f);
      INFO("random map ", i, " (", w, "x", h, "), lookup ", k, " (seed ", test::seed(), ")");
      CAPTURE(uvz);
      ok = CHECK_NEAR(ex02::shadowLookup(m, uvz, 0.01f), shadow::shadowLookup(m, uvz, 0.01f), 0);
    }
  }
}

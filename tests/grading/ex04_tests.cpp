// Graders for lesson 04 (make grade LESSON=04): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases check properties any correct answer has, or compare with
// the reference implementation (compiled into the course library). More cases, with seeds the
// grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "algorithms/shadow_volume.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using volume::StencilOp;

namespace {
Aabb box(glm::vec3 c, float h) {
  Aabb b;
  b.extend(c - glm::vec3(h));
  b.extend(c + glm::vec3(h));
  return b;
}
// Camera at the origin looking down -z, 90 degrees, square, near 1: corners (+-1, +-1, -1).
volume::NearRect unitNear() {
  volume::NearRect r;
  r.corners[0] = {-1, -1, -1};
  r.corners[1] = {1, -1, -1};
  r.corners[2] = {1, 1, -1};
  r.corners[3] = {-1, 1, -1};
  return r;
}
}  // namespace

TEST_CASE("ex04.1: the top-front edge of a box under four lights") {
  // Edge (0,0,0)-(1,0,0). (a, b, c), c = (0,0,-1): n = (1,0,0) x (0,0,-1) = (0,1,0), the top.
  // (b, a, d), d = (0,-1,0): n = (-1,0,0) x (-1,-1,0) = (0,0,1), the front.
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 0, -1), d(0, -1, 0);
  INFO("edge (0,0,0)-(1,0,0), c = (0,0,-1), d = (0,-1,0)");
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, 5, -5, 1}), true);    // sees the top (5 > 0), not the front (-5)
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, 5, 5, 1}), false);    // sees both
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, -5, -5, 1}), false);  // sees neither
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, -5, 5, 1}), true);    // the front only
}

TEST_CASE("ex04.1: directional lights (w = 0) and the edge-on case") {
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 0, -1), d(0, -1, 0);
  INFO("edge (0,0,0)-(1,0,0), c = (0,0,-1), d = (0,-1,0)");
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, 1, 0, 0}), true);    // sun overhead: top 1, front 0 (edge-on)
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, 0, 1, 0}), true);    // sun from the front: top 0, front 1
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, 1, 1, 0}), false);   // both
  CHECK_EXACT(ex04::isSilhouette(a, b, c, d, {0, -1, 0, 0}), false);  // from below: top -1, front 0
}

TEST_CASE("ex04.1: random edges against the reference") {
  std::mt19937_64 rng(test::seedFor("ex04.1"));
  std::uniform_real_distribution<float> u(-5, 5);
  int silhouettes = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng)),
        d(u(rng), u(rng), u(rng));
    const glm::vec4 L(u(rng), u(rng), u(rng), i % 2 ? 1.0f : 0.0f);
    const bool expected = volume::isSilhouette(a, b, c, d, L);
    silhouettes += expected;
    INFO("random case ", i, " of 500 (seed ", test::seed(), ")");
    CAPTURE(a);
    CAPTURE(b);
    CAPTURE(c);
    CAPTURE(d);
    CAPTURE(L);
    if (!CHECK_EXACT(ex04::isSilhouette(a, b, c, d, L), expected)) break;
  }
  CHECK(silhouettes > 50);
}

TEST_CASE("ex04.2: the infinite projection, entry by entry") {
  // fovY = 90 degrees: f = 1 / tan(45) = 1; aspect 2 -> m[0][0] = 0.5; near 0.5, epsilon 0.001:
  // m[2][2] = -0.999, m[3][2] = 0.5 (0.001 - 2) = -0.9995, m[2][3] = -1, every other entry 0.
  const glm::mat4 m = ex04::infinitePerspective(glm::radians(90.0f), 2.0f, 0.5f, 0.001f);
  glm::mat4 e(0.0f);
  e[0][0] = 0.5f;
  e[1][1] = 1.0f;
  e[2][2] = -0.999f;
  e[2][3] = -1.0f;
  e[3][2] = -0.9995f;
  CHECK_NEAR(m, e, 1e-5);
}

TEST_CASE("ex04.2: the near plane maps to -1 and infinity stays inside the clip volume") {
  const float n = 0.1f, eps = 1e-6f;
  const glm::mat4 m = ex04::infinitePerspective(1.0f, 16.0f / 9.0f, n, eps);
  CAPTURE(m);
  const glm::vec4 nearPoint = m * glm::vec4(0.3f, 0.2f, -n, 1);
  CHECK_NEAR(nearPoint.z / nearPoint.w, -1.0f, 1e-5);
  // Direction (0.3, -0.2, -1, 0): z_clip = (eps - 1)(-1) = 1 - eps, w_clip = 1: inside, just.
  const glm::vec4 inf = m * glm::vec4(0.3f, -0.2f, -1, 0);
  CAPTURE(inf);
  CHECK_NEAR(inf.w, 1.0f, 1e-5);
  CHECK(inf.z < inf.w);
  CHECK(inf.z > 0.99f);
  // With epsilon = 0 a point at z = -d has depth 1 - 2 n / d: d = 20 n -> 0.9.
  const glm::vec4 p = ex04::infinitePerspective(1.0f, 1.0f, n, 0.0f) * glm::vec4(0, 0, -20 * n, 1);
  CHECK_NEAR(p.z / p.w, 0.9f, 1e-5);
}

TEST_CASE("ex04.3: z-pass counts in front of the surface") {
  const volume::StencilOps s = ex04::stencilOps(false);
  INFO("StencilOp: 0 Keep, 1 IncrWrap, 2 DecrWrap (volume::StencilOp)");
  CHECK_EXACT(s.front.depthPass, StencilOp::IncrWrap);
  CHECK_EXACT(s.back.depthPass, StencilOp::DecrWrap);
  CHECK_EXACT(s.front.depthFail, StencilOp::Keep);
  CHECK_EXACT(s.back.depthFail, StencilOp::Keep);
  CHECK_EXACT(s.front.stencilFail, StencilOp::Keep);
  CHECK_EXACT(s.back.stencilFail, StencilOp::Keep);
}

TEST_CASE("ex04.3: z-fail counts behind it") {
  const volume::StencilOps s = ex04::stencilOps(true);
  INFO("StencilOp: 0 Keep, 1 IncrWrap, 2 DecrWrap (volume::StencilOp)");
  CHECK_EXACT(s.back.depthFail, StencilOp::IncrWrap);
  CHECK_EXACT(s.front.depthFail, StencilOp::DecrWrap);
  CHECK_EXACT(s.front.depthPass, StencilOp::Keep);
  CHECK_EXACT(s.back.depthPass, StencilOp::Keep);
  CHECK_EXACT(s.front.stencilFail, StencilOp::Keep);
  CHECK_EXACT(s.back.stencilFail, StencilOp::Keep);
}

TEST_CASE("ex04.4: a point light ahead of the camera at z = -10") {
  const volume::NearRect r = unitNear();
  const glm::vec4 L(0, 0, -10, 1);
  INFO("camera at the origin looking down -z, near rectangle (+-1, +-1, -1); light (0, 0, -10)");
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({0, 0, -5}, 0.5f), r, L), true);  // between: shadows the near plane
  // The pyramid's half-width at z = -5 is 1 * (10 - 5) / (10 - 1) = 0.56: a box at x 4.5..5.5 is outside.
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({5, 0, -5}, 0.5f), r, L), false);
  // Beyond the light (z = -20): its shadow points away from the camera.
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({0, 0, -20}, 0.5f), r, L), false);
  // The camera inside the caster.
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({0, 0, 0}, 3.0f), r, L), true);
}

TEST_CASE("ex04.4: the sun behind the camera, and a light in the near plane") {
  const volume::NearRect r = unitNear();
  const glm::vec4 sun(0, 0, 1, 0);  // toward +z: behind the viewer
  INFO("camera at the origin looking down -z, near rectangle (+-1, +-1, -1); sun toward (0, 0, 1)");
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({0, 0, 3}, 0.5f), r, sun), true);    // between the sun and the viewer
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({0, 0, -5}, 0.5f), r, sun), false);  // ahead: shadow runs away
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({4, 0, 3}, 0.5f), r, sun), false);   // behind, off to the side
  CHECK_EXACT(ex04::volumeMayReachNearPlane(box({50, 50, -50}, 0.5f), r, glm::vec4(5, 0, -1, 1)), true);
}

TEST_CASE("ex04.4: never says z-pass when a segment from the near rectangle to the light hits the box") {
  std::mt19937_64 rng(test::seedFor("ex04.4"));
  std::uniform_real_distribution<float> u(-1, 1), t01(0, 1);
  const volume::NearRect r = unitNear();
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::vec4 L =
        i % 2 ? glm::vec4(8 * u(rng), 8 * u(rng), -1 - 10 * t01(rng), 1) : glm::vec4(u(rng), u(rng), u(rng), 0);
    const Aabb b = box({3 * u(rng), 3 * u(rng), -1 - 6 * t01(rng)}, 0.2f + t01(rng));
    // Brute force: segments from points of the rectangle toward the light, sampled along.
    bool hit = false;
    glm::vec3 where(0);
    for (int s = 0; s < 200 && !hit; ++s) {
      const glm::vec3 q(u(rng), u(rng), -1);
      const glm::vec3 dir = L.w != 0 ? glm::vec3(L) - q : glm::vec3(L) * 20.0f;
      where = q + t01(rng) * dir;
      hit = glm::all(glm::greaterThanEqual(where, b.min)) && glm::all(glm::lessThanEqual(where, b.max));
    }
    hits += hit;
    INFO("random case ", i, " of 300 (seed ", test::seed(), "): near rectangle (+-1, +-1, -1)");
    CAPTURE(L);
    CAPTURE(b.min);
    CAPTURE(b.max);
    INFO("a segment from the near rectangle toward the light passes through ", grading::show(where), " in the box");
    if (hit && !CHECK_EXACT(ex04::volumeMayReachNearPlane(b, r, L), true)) break;
  }
  CHECK(hits > 10);
}

// Grader for lesson 08 (make grade LESSON=08): the public cases. Hand-computed cases, then seeded random
// ones that check properties any correct answer has. More cases, with seeds the grader chooses,
// run when your work is graded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using shadowlab::ex08::postProjectiveLight;
using shadowlab::grading::kApprox;

namespace {
// The camera of every hand case: at the origin looking down -z, fovY 90 degrees, aspect 1, n = 1,
// f = 3. Its GL projection: x' = x, y' = y, z' = -2 z - 3 w, w' = -z.
glm::dmat4 handCamera() {
  glm::dmat4 p(0.0);
  p[0][0] = 1.0;
  p[1][1] = 1.0;
  p[2][2] = -2.0;  // -(f + n) / (f - n)
  p[3][2] = -3.0;  // -2 f n / (f - n)
  p[2][3] = -1.0;
  return p;
}
}  // namespace

TEST_CASE("ex08.1: a point light in front of the camera becomes a finite point") {
  // (0,0,-2,1) -> (0, 0, -2*-2 - 3, 2) = (0,0,1,2) -> (0, 0, 0.5), in front.
  CHECK_NEAR(postProjectiveLight(handCamera(), {0, 0, -2, 1}), glm::dvec4(0, 0, 0.5, 1), 1e-12);
  // (1,1,-1,1): on the near plane's corner -> (1, 1, -1), in front.
  CHECK_NEAR(postProjectiveLight(handCamera(), {1, 1, -1, 1}), glm::dvec4(1, 1, -1, 1), 1e-12);
}

TEST_CASE("ex08.1: a point light behind the camera keeps h.xyz/h.w and is marked -1") {
  // (1,0,2,1) -> (1, 0, -7, -2) -> (-0.5, 0, 3.5), behind.
  CHECK_NEAR(postProjectiveLight(handCamera(), {1, 0, 2, 1}), glm::dvec4(-0.5, 0, 3.5, -1), 1e-12);
}

TEST_CASE("ex08.1: directional lights along, against and across the view") {
  // Light from behind (travels along -z): (0,0,1,0) -> (0,0,-2,-1) -> (0,0,2): the plane
  // z = (f+n)/(f-n) = 2 behind the far face, marked behind.
  CHECK_NEAR(postProjectiveLight(handCamera(), {0, 0, 1, 0}), glm::dvec4(0, 0, 2, -1), 1e-12);
  // Light from the front (travels along +z): (0,0,-1,0) -> (0,0,2,1) -> (0,0,2), in front.
  CHECK_NEAR(postProjectiveLight(handCamera(), {0, 0, -1, 0}), glm::dvec4(0, 0, 2, 1), 1e-12);
  // Light from +x (parallel to the near plane): (1,0,0,0) -> (1,0,0,0): stays a direction.
  CHECK_NEAR(postProjectiveLight(handCamera(), {1, 0, 0, 0}), glm::dvec4(1, 0, 0, 0), 1e-12);
  // From (3,4,0) direction: stays a direction, normalised.
  CHECK_NEAR(postProjectiveLight(handCamera(), {3, 4, 0, 0}), glm::dvec4(0.6, 0.8, 0, 0), 1e-12);
}

TEST_CASE("ex08.1: a point light at the eye becomes a direction along -z") {
  // (0,0,0,1) -> (0, 0, -3, 0): w = 0, direction (0,0,-1).
  CHECK_NEAR(postProjectiveLight(handCamera(), {0, 0, 0, 1}), glm::dvec4(0, 0, -1, 0), 1e-12);
}

TEST_CASE("ex08.1: random cameras and point lights: the point maps back and the sign is the side") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex08.1 random"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double fov = 0.3 + 2.0 * (u(rng) * 0.5 + 0.5), n = 0.05 + (u(rng) + 1.0),
                 f = n * (10.0 + 500.0 * (u(rng) + 1.0));
    glm::dmat4 proj(0.0);
    const double t = 1.0 / std::tan(fov / 2.0);
    proj[0][0] = t;
    proj[1][1] = t;
    proj[2][2] = -(f + n) / (f - n);
    proj[3][2] = -2.0 * f * n / (f - n);
    proj[2][3] = -1.0;
    glm::dmat4 view(1.0);  // a rotation about y and a translation
    const double a = 3.0 * u(rng);
    view[0][0] = std::cos(a);
    view[2][0] = std::sin(a);
    view[0][2] = -std::sin(a);
    view[2][2] = std::cos(a);
    view[3] = glm::dvec4(5 * u(rng), 5 * u(rng), 5 * u(rng), 1.0);
    const glm::dmat4 vp = proj * view;
    const glm::dvec3 p(20 * u(rng), 20 * u(rng), 20 * u(rng));
    const double zView = (view * glm::dvec4(p, 1.0)).z;
    if (std::abs(zView) < 1e-3) continue;
    const glm::dvec4 r = postProjectiveLight(vp, glm::dvec4(p, 1.0));
    INFO("random case ", i, " of 200 (seed ", shadowlab::test::seed(), "): fovY ", fov, ", near ", n, ", far ", f);
    CAPTURE(view);
    CAPTURE(p);
    if (!CHECK_NEAR(r.w, zView < 0 ? 1.0 : -1.0, 0)) break;  // in front iff view z < 0
    const glm::dvec4 back = glm::inverse(vp) * glm::dvec4(glm::dvec3(r), 1.0);
    INFO("mapped back by the inverse of viewProj: the light's own position");
    if (!CHECK_NEAR(glm::dvec3(back) / back.w, p, shadowlab::grading::relativeTolerance(1e-6))) break;
  }
}

TEST_CASE("ex08.2: the virtual camera's slide, by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // The hand camera looks down -z from the origin: view = identity, z_view = z.
  using shadowlab::ex08::virtualCameraShift;
  // A corner 4 behind the eye (z = +4) must end 1 in front of it: slide 5.
  CHECK_NEAR(virtualCameraShift(glm::dmat4(1.0), 1.0, {{0, 0, -3}, {1, 1, 4}}), 5.0, kApprox);
  // On the eye plane (z = 0) with near 0.5: 0.5.
  CHECK_NEAR(virtualCameraShift(glm::dmat4(1.0), 0.5, {{7, -2, 0}}), 0.5, kApprox);
  // A camera at (0, 0, 10) looking down -z: view translates by -10; the corner at z = 12 is 2
  // behind it, so with near 1 the slide is 3.
  glm::dmat4 view(1.0);
  view[3][2] = -10.0;
  CHECK_NEAR(virtualCameraShift(view, 1.0, {{0, 0, 12}, {0, 0, 0}}), 3.0, kApprox);
  // Everything in front of the near plane (z <= -1), or nothing at all: no slide.
  CHECK_NEAR(virtualCameraShift(glm::dmat4(1.0), 1.0, {{0, 0, -1}, {3, 2, -5}}), 0.0, kApprox);
  CHECK_NEAR(virtualCameraShift(glm::dmat4(1.0), 1.0, {}), 0.0, kApprox);
}

TEST_CASE("ex08.2: random cameras: after the slide every corner is at least zNear in front") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex08.2 random"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double a = 3.0 * u(rng), zNear = 0.05 + 2.0 * (u(rng) + 1.0);
    glm::dmat4 view(1.0);  // a rotation about y and a translation
    view[0][0] = std::cos(a);
    view[2][0] = std::sin(a);
    view[0][2] = -std::sin(a);
    view[2][2] = std::cos(a);
    view[3] = glm::dvec4(10 * u(rng), 10 * u(rng), 10 * u(rng), 1.0);
    std::vector<glm::dvec3> corners;
    for (int k = 0; k < 1 + i % 7; ++k) corners.push_back({30 * u(rng), 30 * u(rng), 30 * u(rng)});
    const double shift = shadowlab::ex08::virtualCameraShift(view, zNear, corners);
    double worst = -1e300;  // the largest z_view after sliding back by shift (z' = z - shift)
    for (const auto& c : corners) worst = std::max(worst, (view * glm::dvec4(c, 1.0)).z - shift);
    INFO("random case ", i, " of 200 (seed ", shadowlab::test::seed(), "): zNear ", zNear, ", ", corners.size(),
         " corners; your slide ", shift, " leaves the nearest corner at z_view ", worst);
    CAPTURE(view);
    if (!CHECK_TRUE(shift >= 0.0)) break;            // a slide is never negative
    if (!CHECK_TRUE(worst <= -zNear + 1e-9)) break;  // every corner at least zNear in front
    // The slide is the least that does it: either nothing was needed, or one corner sits on the plane.
    if (!CHECK_TRUE(shift == 0.0 || std::abs(worst + zNear) <= 1e-9 * (1.0 + shift))) break;
  }
}

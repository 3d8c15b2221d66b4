// Unit tests for the predicted texel density (algorithms/psm/texel_density) and the PSM plan's fall
// back to the uniform map it drives (psm_plan, PsmSwitches::uniformFallback): hand-derived spacings
// and samples, then the switch.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/psm/psm_plan.hpp"
#include "algorithms/psm/texel_density.hpp"

using namespace shadowlab;
using namespace shadowlab::psm;

namespace {

// An orthographic map along -z over x, y in [-10, 10]: one texel of a 1000 map is 0.02 wide.
const glm::dmat4 kOrtho = glm::ortho(-10.0, 10.0, -10.0, 10.0, 0.0, 100.0);

// Eye at the origin looking down -z; fovY 90 degrees, aspect 1, near 1, far 100.
CameraFrustum originCamera() { return makeCamera(glm::dmat4(1.0), std::numbers::pi / 2, 1.0, 1.0, 100.0); }

}  // namespace

TEST_CASE("psm texel density: the rays' spacing of an orthographic map, along and across the light") {
  // The one-texel step is (0.02, 0.02, 0): across a light along -z it is all spacing.
  CHECK(rayTexelSpacing(kOrtho, 1000, {3, -4, -20}, {0, 0, -1}) == doctest::Approx(0.02 * std::sqrt(2.0)));
  // A light at 45 degrees in x-z: the step's part along it, 0.02 / sqrt 2, is no spacing.
  const double across = std::sqrt(2 * 0.02 * 0.02 - 0.02 * 0.02 / 2);
  CHECK(rayTexelSpacing(kOrtho, 1000, {3, -4, -20}, {1, 0, -1}) == doctest::Approx(across));
  CHECK(rayTexelSpacing(kOrtho, 2000, {0, 0, -5}, {0, 0, -1}) == doctest::Approx(0.01 * std::sqrt(2.0)));
}

TEST_CASE("psm texel density: screen samples are the middle of each ray's way through the nearest volume") {
  std::vector<glm::dvec3> samples;
  const std::vector<Aabb> wall{Aabb{{-50, -50, -12}, {50, 50, -8}}};
  screenSamples(originCamera(), wall, 4, 3, samples);
  REQUIRE(samples.size() == 12);
  for (const glm::dvec3& p : samples) CHECK(p.z == doctest::Approx(-10.0));  // entry -8, exit -12
  // The nearer of two volumes on the way; a ray meeting none adds nothing.
  const std::vector<Aabb> two{Aabb{{-50, -50, -42}, {50, 50, -38}}, Aabb{{0, -50, -22}, {50, 50, -18}}};
  screenSamples(originCamera(), two, 4, 2, samples);
  REQUIRE(samples.size() == 8);
  for (const glm::dvec3& p : samples) CHECK(p.z == doctest::Approx(p.x > 0 ? -20.0 : -40.0));
  const std::vector<Aabb> left{Aabb{{-50, -50, -12}, {-0.001f, 50, -8}}};
  screenSamples(originCamera(), left, 4, 2, samples);
  CHECK(samples.size() == 4);
  // The eye inside a volume: from the eye to where the ray leaves it.
  const std::vector<Aabb> around{Aabb{{-50, -50, -12}, {50, 50, 5}}};
  screenSamples(originCamera(), around, 2, 2, samples);
  REQUIRE(samples.size() == 4);
  for (const glm::dvec3& p : samples) CHECK(p.z == doctest::Approx(-6.0));
}

TEST_CASE("psm texel density: the mean aliasing is spacing over view depth, in the first map holding each point") {
  const std::vector<glm::dvec3> points{{0, 0, -10}, {1, 1, -20}, {40, 0, -10}};  // the last outside the map
  const glm::dmat4 maps[] = {kOrtho};
  const TexelDensity d = predictTexelDensity(glm::dmat4(1.0), points, maps, 1000, glm::dvec4(0, 0, 1, 0));
  CHECK(d.points == 2);
  const double s = 0.02 * std::sqrt(2.0);
  CHECK(d.maxSpacing == doctest::Approx(s));
  CHECK(d.meanAliasing == doctest::Approx((s / 10 + s / 20) / 2));
  // A second, finer map for the third point only: it counts there.
  const glm::dmat4 two[] = {kOrtho, glm::ortho(30.0, 50.0, -10.0, 10.0, 0.0, 100.0)};
  CHECK(predictTexelDensity(glm::dmat4(1.0), points, two, 1000, glm::dvec4(0, 0, 1, 0)).points == 3);
}

TEST_CASE("psm plan: the fall back to the uniform map follows the predicted densities, and only when switched on") {
  // A street: a ground slab and blocks ahead of an eye 2 m up looking down -z; a low sun from behind.
  const CameraFrustum camera = makeCamera(glm::lookAt(glm::dvec3(0, 2, 10), glm::dvec3(0, 2, 0), glm::dvec3(0, 1, 0)),
                                          std::numbers::pi / 2, 1.0, 1.0, 100.0);
  const std::vector<Aabb> street{Aabb{{-20, 0, -60}, {20, 0.01f, 9}}, Aabb{{-3, 0, -5}, {-1, 4, -3}},
                                 Aabb{{2, 0, -20}, {4, 6, -18}}, Aabb{{-2, 0, -40}, {0, 8, -38}}};
  const glm::dvec4 sun(0.2, 1.0, 0.4, 0.0);
  PsmPlanner planner;
  PsmSwitches s;
  s.mapSide = 1024;
  const PsmPlan& off = planner.plan(camera, sun, street, street, {}, s);
  REQUIRE(off.status == PlanStatus::Ok);
  CHECK_FALSE(off.fallback);
  REQUIRE(off.uniform.points > 0);  // predicted with the switch off too (the header shows it)
  CHECK(off.warped.points == off.uniform.points);
  const double ratio = off.warped.meanAliasing / off.uniform.meanAliasing;
  CHECK(std::isfinite(ratio));
  s.uniformFallback = true;
  s.fallbackRatio = ratio * 1.01;  // the warp predicted better than this: it stays
  const PsmPlan& kept = planner.plan(camera, sun, street, street, {}, s);
  CHECK_FALSE(kept.fallback);
  CHECK(kept.maps[0].camera.kind != LightProjection::Orthographic);
  s.fallbackRatio = ratio * 0.99;  // predicted worse: the uniform map, holding every key point
  const PsmPlan& fell = planner.plan(camera, sun, street, street, {}, s);
  REQUIRE(fell.fallback);
  CHECK(fell.mapCount == 1);
  CHECK_FALSE(fell.faces);
  CHECK(fell.maps[0].camera.kind == LightProjection::Orthographic);
  for (const glm::dvec3& p : planner.worldKeyPoints()) {
    const glm::dvec4 h = fell.maps[0].camera.worldToClip * glm::dvec4(p, 1.0);
    CHECK(h.w == doctest::Approx(1.0));
    CHECK(glm::all(glm::lessThanEqual(glm::abs(glm::dvec3(h)), glm::dvec3(1.0 + 1e-6))));
  }
  // Its post-projective matrix is the world one after the camera's inverse: the view draws it.
  const glm::dvec4 q = fell.camera.viewProj * glm::dvec4(planner.worldKeyPoints()[0], 1.0);
  const glm::dvec4 a = fell.maps[0].camera.postToClip * q,
                   b = fell.maps[0].camera.worldToClip * glm::dvec4(planner.worldKeyPoints()[0], 1.0);
  CHECK(glm::length(glm::dvec3(a) / a.w - glm::dvec3(b) / b.w) < 1e-9);
  // A point light: no uniform map to fall back to, no prediction.
  const PsmPlan& lamp = planner.plan(camera, glm::dvec4(0, 30, -80, 1), street, street, {}, s);
  CHECK_FALSE(lamp.fallback);
  CHECK(lamp.uniform.points == 0);
}

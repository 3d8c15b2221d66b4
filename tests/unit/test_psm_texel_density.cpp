// Unit tests for the predicted aliasing (algorithms/psm/texel_density) and the PSM plan's fall back
// to the uniform map it drives (psm_plan, PsmSwitches::uniformFallback): hand-derived spacings,
// samples and m, then the switch.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/psm/psm_plan.hpp"
#include "algorithms/psm/texel_density.hpp"
#include "core/mesh_gen.hpp"
#include "core/scene.hpp"

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

TEST_CASE("psm texel density: screen samples are where each ray enters the nearest volume, with that face's normal") {
  std::vector<SurfaceSample> samples;
  const std::vector<Aabb> wall{Aabb{{-50, -50, -12}, {50, 50, -8}}};
  screenSurfaceSamples(originCamera(), wall, 4, 3, samples);
  REQUIRE(samples.size() == 12);
  for (const SurfaceSample& s : samples) {
    CHECK(s.point.z == doctest::Approx(-8.0));  // its face toward the eye
    CHECK(s.normal == glm::dvec3(0, 0, 1));
  }
  // The nearer of two volumes on the way; a ray meeting none adds nothing.
  const std::vector<Aabb> two{Aabb{{-50, -50, -42}, {50, 50, -38}}, Aabb{{0, -50, -22}, {50, 50, -18}}};
  screenSurfaceSamples(originCamera(), two, 4, 2, samples);
  REQUIRE(samples.size() == 8);
  for (const SurfaceSample& s : samples) CHECK(s.point.z == doctest::Approx(s.point.x > 0 ? -18.0 : -38.0));
  const std::vector<Aabb> left{Aabb{{-50, -50, -12}, {-0.001f, 50, -8}}};
  screenSurfaceSamples(originCamera(), left, 4, 2, samples);
  CHECK(samples.size() == 4);
  // A block beside the view: the rays at x > 0 enter it through its side face x = 2 (normal -x).
  const std::vector<Aabb> side{Aabb{{2, -50, -60}, {50, 50, -1.5f}}};
  screenSurfaceSamples(originCamera(), side, 4, 1, samples);
  REQUIRE(samples.size() == 2);
  for (const SurfaceSample& s : samples) {
    CHECK(s.point.x == doctest::Approx(2.0));
    CHECK(s.normal == glm::dvec3(-1, 0, 0));
  }
  // The eye inside a volume: where the ray leaves it, the face turned to the eye.
  const std::vector<Aabb> around{Aabb{{-50, -50, -12}, {50, 50, 5}}};
  screenSurfaceSamples(originCamera(), around, 2, 2, samples);
  REQUIRE(samples.size() == 4);
  for (const SurfaceSample& s : samples) {
    CHECK(s.point.z == doctest::Approx(-12.0));
    CHECK(s.normal == glm::dvec3(0, 0, 1));
  }
}

namespace {
// A scene of boxes (full size `size`, centred at `at`), each with its own material.
Scene boxes(const std::vector<std::pair<glm::vec3, glm::vec3>>& placed, bool twoSided = false) {
  Scene scene;
  for (const auto& [at, size] : placed) {
    Material m;
    m.twoSided = twoSided;
    SceneObject o;
    o.mesh = scene.addMesh(makeBox(size));
    o.material = scene.addMaterial(m);
    o.model = glm::translate(glm::mat4(1.0f), at);
    scene.addObject(o);
  }
  return scene;
}
}  // namespace

TEST_CASE("psm texel density: scene samples are where each ray meets the nearest drawn triangle") {
  std::vector<SurfaceSample> samples;
  // A wall 4 deep whose front face is at z = -8: every ray meets it there, normal toward the eye.
  screenSceneSamples(originCamera(), boxes({{{0, 0, -10}, {100, 100, 4}}}), 4, 3, samples);
  REQUIRE(samples.size() == 12);
  for (const SurfaceSample& s : samples) {
    CHECK(s.point.z == doctest::Approx(-8.0));
    CHECK(s.normal == glm::dvec3(0, 0, 1));
  }
  // The nearer of two on the way (a block over x > 0 in front of the wall); a ray meeting none adds nothing.
  screenSceneSamples(originCamera(), boxes({{{0, 0, -40}, {100, 100, 4}}, {{25, 0, -20}, {50, 100, 4}}}), 4, 2,
                     samples);
  REQUIRE(samples.size() == 8);
  for (const SurfaceSample& s : samples) CHECK(s.point.z == doctest::Approx(s.point.x > 0 ? -18.0 : -38.0));
  screenSceneSamples(originCamera(), boxes({{{-25, 0, -10}, {50, 100, 4}}}), 4, 2, samples);
  CHECK(samples.size() == 4);
  // The eye inside a block sees through its walls, as the lit pass draws them (back faces culled):
  // the wall behind them. A two-sided block is drawn from inside: its own far face.
  const std::vector<std::pair<glm::vec3, glm::vec3>> inside{{{0, 0, 0}, {10, 10, 10}}, {{0, 0, -30}, {100, 100, 4}}};
  screenSceneSamples(originCamera(), boxes(inside), 2, 2, samples);
  REQUIRE(samples.size() == 4);
  for (const SurfaceSample& s : samples) CHECK(s.point.z == doctest::Approx(-28.0));
  screenSceneSamples(originCamera(), boxes(inside, true), 2, 2, samples);
  REQUIRE(samples.size() == 4);
  for (const SurfaceSample& s : samples) {
    CHECK(s.point.z == doctest::Approx(-5.0));
    CHECK(s.normal == glm::dvec3(0, 0, 1));  // turned toward the eye
  }
  // An object that receives no shadow is not looked at.
  Scene hidden = boxes({{{0, 0, -10}, {100, 100, 4}}, {{0, 0, -30}, {100, 100, 4}}});
  hidden.objects[0].receivesShadow = false;
  screenSceneSamples(originCamera(), hidden, 2, 2, samples);
  REQUIRE(samples.size() == 4);
  for (const SurfaceSample& s : samples) CHECK(s.point.z == doctest::Approx(-28.0));
}

TEST_CASE("psm texel density: m, screen pixels per texel on the receiver, and its mean over the samples a map holds") {
  // 100 pixels high, fovY 90: at 10 m a pixel is 0.2 m, at 20 m 0.4 m; the map's texel is 0.02 m.
  const CameraFrustum camera = originCamera();
  const SurfaceSample facing{{0, 0, -10}, {0, 0, 1}};
  CHECK(pixelAliasing(camera, 100, facing, kOrtho, 1000) == doctest::Approx(0.1));  // 10 texels a pixel
  CHECK(pixelAliasing(camera, 100, {{1, 1, -20}, {0, 0, 1}}, kOrtho, 1000) == doctest::Approx(0.05));
  CHECK(pixelAliasing(camera, 1000, facing, kOrtho, 1000) == doctest::Approx(1.0));  // 0.02 m pixels
  // A wall along the light (normal +x, the map looking down -z): moving along it in depth changes
  // no texel, so one screen direction gets none: m is the cap.
  CHECK(pixelAliasing(camera, 100, {{3, 0, -10}, {-1, 0, 0}}, kOrtho, 1000) == 1024.0);
  CHECK(pixelAliasing(camera, 100, {{3, 0, -10}, {-1, 0, 0}}, kOrtho, 1000, 64.0) == 64.0);
  // Tilted 60 degrees about y: a pixel across x stretches to 0.2 / (0.5 - 0.866 * 0.02) m, still
  // over 10 texels along y: m stays 0.1 (sigma_min is the shorter side).
  const SurfaceSample tilted{{0, 0, -10}, {std::sqrt(3.0) / 2, 0, 0.5}};
  CHECK(pixelAliasing(camera, 100, tilted, kOrtho, 1000) == doctest::Approx(0.1));
  // Behind the map's eye: no texel.
  CHECK(std::isinf(pixelAliasing(
      camera, 100, facing,
      glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, -1)),
      1000)));
  // The mean over the samples the map holds (the third is outside it), the coarsest ray spacing.
  const std::vector<SurfaceSample> samples{facing, {{1, 1, -20}, {0, 0, 1}}, {{40, 0, -10}, {0, 0, 1}}};
  const glm::dmat4 maps[] = {kOrtho};
  const TexelDensity d = predictAliasing(camera, 100, samples, maps, 1000, glm::dvec4(0, 0, 1, 0));
  CHECK(d.points == 2);
  CHECK(d.meanAliasing == doctest::Approx((0.1 + 0.05) / 2));
  CHECK(d.maxSpacing == doctest::Approx(0.02 * std::sqrt(2.0)));
  // A second, finer map for the third point only: it counts there.
  const glm::dmat4 two[] = {kOrtho, glm::ortho(30.0, 50.0, -10.0, 10.0, 0.0, 100.0)};
  CHECK(predictAliasing(camera, 100, samples, two, 1000, glm::dvec4(0, 0, 1, 0)).points == 3);
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

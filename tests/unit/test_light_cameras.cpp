// algorithms/light_cameras: the light cameras of the uniform shadow-map technique (lesson 03),
// checked on small scenes whose answers follow from the geometry.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/light_cameras.hpp"

using namespace shadowlab;
using namespace shadowlab::shadow;

namespace {

// A viewer at (0, 2, 10) looking at the origin, 60 degrees, 16:9, near 0.1, far 40.
ConvexVolume viewerVolume() {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 2, 10), glm::vec3(0), glm::vec3(0, 1, 0));
  return volumeFromViewProj(glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 40.0f) * view);
}

// Three unit boxes: one in view, one far behind the viewer, one in view that does not cast; and a
// 100 m ground box under everything.
struct Boxes {
  std::vector<Aabb> boxes{{{-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}},
                          {{-0.5f, 0, 59.5f}, {0.5f, 1, 60.5f}},
                          {{2, 0, 0}, {3, 1, 1}},
                          {{-50, -1, -50}, {50, 0, 50}}};
  std::vector<char> casts{1, 1, 0, 1};
  CasterBoxes get() const { return {boxes, casts, {{-50, -1, -50}, {50, 1, 60.5f}}}; }
};

// Where a world point lands in a camera's clip cube (w-divided).
glm::vec3 ndc(const LightCamera& c, const glm::vec3& p) {
  const glm::vec4 h = c.viewProj() * glm::vec4(p, 1);
  return glm::vec3(h) / h.w;
}

bool insideCube(const glm::vec3& p, float slack = 1e-3f) {
  return glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(1 + slack)));
}

}  // namespace

TEST_CASE("light cameras: a directional fit culls the caster behind the viewer and keeps non-casters out") {
  const Boxes b;
  // Straight down: the box 60 m behind the viewer can shade nothing the view contains.
  const LightCamera c = fitDirectional({0, -1, 0}, b.get(), viewerVolume(), {});
  REQUIRE(c.casters.size() == 4);
  CHECK(c.casters[0] == 1);  // in view
  CHECK(c.casters[1] == 0);  // culled
  CHECK(c.casters[2] == 0);  // casts no shadow at all: never drawn, not counted as culled
  CHECK(c.casters[3] == 1);  // the ground under the view
  CHECK(c.culled == 1);
  CHECK(c.texelWorld > 0.0f);
  // Without culling every caster is drawn.
  DirectionalFitOptions all;
  all.cullCasters = false;
  const LightCamera d = fitDirectional({0, -1, 0}, b.get(), viewerVolume(), all);
  CHECK(d.culled == 0);
  CHECK(d.casters == std::vector<char>{1, 1, 0, 1});
}

TEST_CASE(
    "light cameras: a scene fit holds every corner of the scene, a view fit is smaller and holds the view's "
    "receivers") {
  const Boxes b;
  DirectionalFitOptions scene;
  scene.fitToView = false;
  const glm::vec3 sun = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  const LightCamera whole = fitDirectional(sun, b.get(), viewerVolume(), scene);
  for (const glm::vec3& corner : volumeFromBox(b.get().bounds).corners) CHECK(insideCube(ndc(whole, corner)));
  const LightCamera fitted = fitDirectional(sun, b.get(), viewerVolume(), {});
  // The receivers the view needs: the ground and the scene inside the view frustum.
  for (const glm::vec3& p : intersectionPoints(volumeFromBox(b.get().bounds), viewerVolume()))
    CHECK(insideCube(ndc(fitted, p), 0.05f));
  CHECK(fitted.texelWorld < whole.texelWorld);  // fewer metres per texel: the point of fitting
}

TEST_CASE("light cameras: the replaceable steps are the ones used (impl=student)") {
  const Boxes b;
  DirectionalFitOptions o;
  o.casterTest = [](const Aabb&, const ConvexVolume&, const glm::vec3&) { return false; };
  const LightCamera none = fitDirectional({0, -1, 0}, b.get(), viewerVolume(), o);
  CHECK(none.culled == 3);
  CHECK(none.casters == std::vector<char>{0, 0, 0, 0});
  int fits = 0;
  o.fitter = [&](const glm::vec3& d, std::span<const glm::vec3> r, std::span<const Aabb> c, int size, bool snap) {
    ++fits;
    return fitOrthographic(d, r, c, size, snap);
  };
  fitDirectional({0, -1, 0}, b.get(), viewerVolume(), o);
  CHECK(fits == 1);
}

TEST_CASE("light cameras: the spot's frustum holds its cone and culls what is behind it") {
  Boxes b;
  Light spot{LightKind::Spot, {0, 10, 0}};
  spot.direction = {0, -1, 0};
  spot.spotOuter = 0.5f;
  CHECK(spotFieldOfView(spot) == doctest::Approx(1.05f));
  spot.spotOuter = 1.6f;
  CHECK(spotFieldOfView(spot) == doctest::Approx(3.0f));  // capped below 180 degrees
  spot.spotOuter = 0.5f;
  b.boxes[1] = {{-0.5f, 20, -0.5f}, {0.5f, 21, 0.5f}};  // above the spot: behind it
  const LightCamera c = spotCamera(spot, 0.5f, 150.0f, b.get(), true);
  CHECK(c.casters == std::vector<char>{1, 0, 0, 1});
  CHECK(c.culled == 1);
  // The axis lands in the middle of the map, the cone's edge inside it.
  CHECK(glm::length(glm::vec2(ndc(c, {0, 0, 0}))) < 1e-4f);
  CHECK(insideCube(ndc(c, {std::tan(0.5f) * 10.0f * 0.99f, 0, 0})));
  // A far plane below the near plane is lifted to near + 0.1 rather than inverting the frustum.
  CHECK_NOTHROW(spotCamera(spot, 5.0f, 1.0f, b.get(), true));
}

TEST_CASE("light cameras: cube faces the view frustum misses are skipped") {
  const Boxes b;
  // A point light behind the viewer, at (0, 2, 20): the viewer looks along -z, away from it, so
  // the +Z face (looking further back) cannot see anything the viewer sees.
  const auto faces = cubeCameras({0, 2, 20}, 0.2f, 60.0f, b.get(), viewerVolume(), true, true);
  CHECK(faces[4].skipped);   // +Z
  CHECK(!faces[5].skipped);  // -Z: toward the scene
  for (int f = 0; f < 6; ++f) {
    CHECK(faces[std::size_t(f)].view == cubeFaceView({0, 2, 20}, f));
    CHECK(faces[std::size_t(f)].casters.size() == b.boxes.size());
    if (faces[std::size_t(f)].skipped) CHECK(faces[std::size_t(f)].casters == std::vector<char>{0, 0, 0, 0});
  }
  const auto all = cubeCameras({0, 2, 20}, 0.2f, 60.0f, b.get(), viewerVolume(), true, false);
  for (const LightCamera& f : all) CHECK(!f.skipped);
}

TEST_CASE("light cameras: inconsistent inputs are refused") {
  const std::vector<Aabb> boxes{{{0, 0, 0}, {1, 1, 1}}};
  const std::vector<char> casts{1, 1};
  const CasterBoxes bad{boxes, casts, boxes[0]};
  Light spot{LightKind::Spot, {0, 10, 0}};
  CHECK_THROWS_AS(fitDirectional({0, -1, 0}, bad, viewerVolume(), {}), std::invalid_argument);
  CHECK_THROWS_AS(spotCamera(spot, 0.5f, 100.0f, bad, true), std::invalid_argument);
  CHECK_THROWS_AS(cubeCameras({0, 0, 0}, 0.1f, 10.0f, bad, viewerVolume(), true, true), std::invalid_argument);
}

// algorithms/light_cameras: fitMap2D, the light camera every 2D-map technique (uniform maps,
// hybrid maps) fits with, against the pieces it is made of and points whose place is known.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/light_cameras.hpp"

using namespace shadowlab;
using namespace shadowlab::shadow;

namespace {

struct Scene {
  std::vector<Aabb> boxes{{{-1, 0, -1}, {1, 2, 1}}, {{-20, -1, -20}, {20, 0, 20}}};
  std::vector<char> casts{1, 1};
  CasterBoxes get() const { return {boxes, casts, {{-20, -1, -20}, {20, 2, 20}}}; }
};

ConvexVolume viewer() {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 4, 12), glm::vec3(0), glm::vec3(0, 1, 0));
  return volumeFromViewProj(glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 60.0f) * view);
}

}  // namespace

TEST_CASE("fitMap2D: a sun gets the fitted orthographic camera, its texture matrix and its world texel") {
  const Scene s;
  Light sun{LightKind::Directional};
  sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  DirectionalFitOptions o;
  o.mapSize = 1024;
  const Map2DCamera m = fitMap2D(sun, s.get(), viewer(), o, 0.5f, 100.0f);
  const LightCamera alone = fitDirectional(sun.direction, s.get(), viewer(), o);
  CHECK_FALSE(m.perspective);
  CHECK(m.camera.viewProj() == alone.viewProj());
  CHECK(m.texel == alone.texelWorld);
  CHECK(m.textureMatrix == textureMatrix(alone.projection, alone.view));
  // The caster's top centre lands inside the map, with a depth in [0, 1].
  const glm::vec3 uvz = shadowCoord(m.textureMatrix, {0, 2, 0});
  CHECK(uvz.x > 0.0f);
  CHECK(uvz.x < 1.0f);
  CHECK(uvz.z >= 0.0f);
  CHECK(uvz.z <= 1.0f);
}

TEST_CASE("fitMap2D: a spot gets its perspective frustum and a texel of 2 tan(fov / 2) / size") {
  const Scene s;
  Light spot{LightKind::Spot, {0, 10, 0}};
  spot.direction = {0, -1, 0};
  spot.spotOuter = 0.5f;
  DirectionalFitOptions o;
  o.mapSize = 512;
  const Map2DCamera m = fitMap2D(spot, s.get(), viewer(), o, 0.5f, 100.0f);
  CHECK(m.perspective);
  CHECK(m.camera.viewProj() == spotCamera(spot, 0.5f, 100.0f, s.get(), true).viewProj());
  CHECK(m.texel == doctest::Approx(2.0f * std::tan(0.5f * spotFieldOfView(spot)) / 512.0f));
  // Straight below the spot: the centre of its map.
  const glm::vec3 uvz = shadowCoord(m.textureMatrix, {0, 0, 0});
  CHECK(uvz.x == doctest::Approx(0.5f));
  CHECK(uvz.y == doctest::Approx(0.5f));
}

TEST_CASE("fitMap2D: a point light has no 2D map") {
  const Scene s;
  CHECK_THROWS_WITH_AS(fitMap2D(Light{LightKind::Point, {0, 5, 0}}, s.get(), viewer(), {}, 0.5f, 100.0f),
                       doctest::Contains("point light"), std::invalid_argument);
}

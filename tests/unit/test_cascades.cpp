// algorithms/psm/cascades and algorithms/cascade_cameras: which cascade shades a depth and how much
// of the next is blended in, each cascade's side at equal total texels, and the cascades' light
// cameras on a small scene whose answers follow from the geometry.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/cascade_cameras.hpp"
#include "algorithms/psm/cascades.hpp"

using namespace shadowlab;

TEST_CASE("cascades: the cascade of a depth and the blend band at its far end") {
  const std::vector<double> splits{1.0, 5.0, 9.0};  // cascade 0 is 4 m deep: a band of 0.25 is its last 1 m
  CHECK(psm::cascadeAt(splits, 3.0, 0.25).cascade == 0);
  CHECK(psm::cascadeAt(splits, 3.0, 0.25).nextWeight == 0.0);
  CHECK(psm::cascadeAt(splits, 4.5, 0.25).cascade == 0);
  CHECK(psm::cascadeAt(splits, 4.5, 0.25).nextWeight == doctest::Approx(0.5));
  CHECK(psm::cascadeAt(splits, 5.0, 0.25).nextWeight == doctest::Approx(1.0));  // all of cascade 1: no seam
  CHECK(psm::cascadeAt(splits, 5.5, 0.25).cascade == 1);
  CHECK(psm::cascadeAt(splits, 8.9, 0.25).nextWeight == 0.0);  // the last cascade blends into nothing
  CHECK(psm::cascadeAt(splits, 4.5, 0.0).nextWeight == 0.0);   // no band: a hard switch
  CHECK(psm::cascadeAt(splits, 0.5, 0.25).cascade == -1);      // nearer than the near plane
  CHECK(psm::cascadeAt(splits, 9.5, 0.25).cascade == -1);      // beyond the last cascade
}

TEST_CASE("cascades: each cascade's side at equal total texels") {
  CHECK(psm::cascadeSide(2048, 1) == 2048);
  CHECK(psm::cascadeSide(2048, 4) == 1024);  // four 1024^2 maps hold 2048^2 texels
  CHECK(psm::cascadeSide(2048, 2) == 1448);  // 2048 / sqrt(2) = 1448.15
  CHECK(psm::cascadeSide(4096, 3) == 2364);  // 4096 / sqrt(3) = 2364.83
  CHECK_THROWS_AS(psm::cascadeSide(2048, 0), std::invalid_argument);
  CHECK_THROWS_AS(psm::cascadeSide(0, 2), std::invalid_argument);
}

namespace {

// A viewer at (0, 2, 20) looking along -z, 60 degrees, square, near 1, far 200, inside a 100 m block
// of scene 5 m high (y -1 .. 4): the view's axis runs through receivers all the way.
shadow::CascadeViewer viewer() {
  shadow::CascadeViewer v;
  v.view = glm::lookAt(glm::vec3(0, 2, 20), glm::vec3(0, 2, 0), glm::vec3(0, 1, 0));
  v.fovY = glm::radians(60.0f);
  v.aspect = 1.0f;
  v.nearZ = 1.0f;
  v.farZ = 200.0f;
  return v;
}

struct Ground {
  std::vector<Aabb> boxes{{{-50, -1, -50}, {50, 4, 50}}};
  std::vector<char> casts{1};
  shadow::CasterBoxes get() const { return {boxes, casts, boxes[0]}; }
};

bool inMap(const shadow::LightCamera& c, const glm::vec3& p) {
  const glm::vec4 h = c.viewProj() * glm::vec4(p, 1.0f);
  return glm::all(glm::lessThanEqual(glm::abs(glm::vec3(h) / h.w), glm::vec3(1.001f)));
}

}  // namespace

TEST_CASE("cascades: the far end is the deepest corner of the scene in view") {
  // The ground's far corners are at z = -50, 70 m in front of the viewer at z = 20.
  CHECK(shadow::cascadeFar(viewer(), Ground{}.boxes[0]) == doctest::Approx(70.0));
  shadow::CascadeViewer behind = viewer();
  behind.view = glm::lookAt(glm::vec3(0, 2, 60), glm::vec3(0, 2, 80), glm::vec3(0, 1, 0));  // looking away
  CHECK(shadow::cascadeFar(behind, Ground{}.boxes[0]) == doctest::Approx(200.0));
}

TEST_CASE("cascades: each slice's light camera holds its receivers and the near ones have the finer texels") {
  const Ground g;
  shadow::CascadeOptions o;
  o.count = 4;
  o.lambda = 1.0;  // logarithmic: 1, 70^(1/4) = 2.89, 70^(1/2) = 8.37, 70^(3/4) = 24.2, 70
  o.fit.mapSize = 1024;
  const shadow::CascadeSet set = shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o);
  REQUIRE(set.splits.size() == 5);
  REQUIRE(set.cameras.size() == 4);
  CHECK(set.splits[2] == doctest::Approx(8.3666).epsilon(1e-3));
  for (int i = 0; i < 4; ++i) {
    // The point on the view's axis at the middle of slice i is in cascade i's map.
    const double mid = 0.5 * (set.splits[std::size_t(i)] + set.splits[std::size_t(i) + 1]);
    CHECK(inMap(set.cameras[std::size_t(i)], {0.0f, 2.0f, 20.0f - float(mid)}));
    if (i > 0) CHECK(set.cameras[std::size_t(i)].texelWorld > set.cameras[std::size_t(i) - 1].texelWorld);
  }
  // The first cascade covers under 3 m of depth: the axis 30 m ahead is not in it.
  CHECK_FALSE(inMap(set.cameras[0], {0.0f, 2.0f, -10.0f}));
  o.count = 5;
  CHECK_THROWS_AS(shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o), std::invalid_argument);
}

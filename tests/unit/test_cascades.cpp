// algorithms/cascades and algorithms/cascades: which cascade shades a depth and how much
// of the next is blended in, each cascade's side at equal total texels, and the cascades' light
// cameras on a small scene whose answers follow from the geometry.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/cascades.hpp"

using namespace shadowlab;

TEST_CASE("cascades: the cascade of a depth and the blend band at its far end") {
  const std::vector<double> splits{1.0, 5.0, 9.0};  // cascade 0 is 4 m deep: a band of 0.25 is its last 1 m
  CHECK(shadow::cascadeAt(splits, 3.0, 0.25).cascade == 0);
  CHECK(shadow::cascadeAt(splits, 3.0, 0.25).nextWeight == 0.0);
  CHECK(shadow::cascadeAt(splits, 4.5, 0.25).cascade == 0);
  CHECK(shadow::cascadeAt(splits, 4.5, 0.25).nextWeight == doctest::Approx(0.5));
  CHECK(shadow::cascadeAt(splits, 5.0, 0.25).nextWeight == doctest::Approx(1.0));  // all of cascade 1: no seam
  CHECK(shadow::cascadeAt(splits, 5.5, 0.25).cascade == 1);
  CHECK(shadow::cascadeAt(splits, 8.9, 0.25).nextWeight == 0.0);  // the last cascade blends into nothing
  CHECK(shadow::cascadeAt(splits, 4.5, 0.0).nextWeight == 0.0);   // no band: a hard switch
  CHECK(shadow::cascadeAt(splits, 0.5, 0.25).cascade == -1);      // nearer than the near plane
  CHECK(shadow::cascadeAt(splits, 9.5, 0.25).cascade == -1);      // beyond the last cascade
}

TEST_CASE("cascades: each cascade's side at equal total texels") {
  CHECK(shadow::cascadeSide(2048, 1) == 2048);
  CHECK(shadow::cascadeSide(2048, 4) == 1024);  // four 1024^2 maps hold 2048^2 texels
  CHECK(shadow::cascadeSide(2048, 2) == 1448);  // 2048 / sqrt(2) = 1448.15
  CHECK(shadow::cascadeSide(4096, 3) == 2364);  // 4096 / sqrt(3) = 2364.83
  CHECK_THROWS_AS(shadow::cascadeSide(2048, 0), std::invalid_argument);
  CHECK_THROWS_AS(shadow::cascadeSide(0, 2), std::invalid_argument);
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

namespace {

// The ground, and a row of 1 m posts along the view's axis every 4 m from z = 16 to z = -48:
// the near cascade's light volume holds only the first few, the far one only the far ones.
struct Posts {
  std::vector<Aabb> boxes{{{-50, -1, -50}, {50, 0, 50}}};
  std::vector<char> casts{1};
  Posts() {
    for (float z = 16.0f; z >= -48.0f; z -= 4.0f) {
      boxes.push_back({{-0.5f, 0.0f, z - 0.5f}, {0.5f, 3.0f, z + 0.5f}});
      casts.push_back(1);
    }
  }
  shadow::CasterBoxes get() const { return {boxes, casts, {{-50, -1, -50}, {50, 4, 50}}}; }
};

int kept(const std::vector<char>& casters) {
  int n = 0;
  for (char c : casters) n += c != 0;
  return n;
}

}  // namespace

TEST_CASE("cascades: each cascade draws only the casters that reach its light volume") {
  const Posts scene;
  shadow::CascadeOptions o;
  o.count = 4;
  o.lambda = 1.0;
  o.fit.mapSize = 1024;
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const shadow::CascadeSet set = shadow::fitCascades(sun, scene.get(), viewer(), o);
  REQUIRE(set.cameras.size() == 4);
  const int casters = int(scene.boxes.size());
  int sumCulled = 0;
  for (const shadow::LightCamera& cam : set.cameras) {
    // Every cascade's casters are some of the union, and what it leaves out is counted.
    for (std::size_t k = 0; k < scene.boxes.size(); ++k) CHECK((!cam.casters[k] || set.casters[k]));
    CHECK(cam.culled == casters - kept(cam.casters));
    // A caster left out has its box outside the cascade's light frustum: it writes no texel of it.
    for (std::size_t k = 0; k < scene.boxes.size(); ++k)
      if (set.casters[k] && !cam.casters[k]) {
        const shadow::ConvexVolume box = shadow::volumeFromBox(scene.boxes[k]);
        CHECK_FALSE(shadow::volumesMayIntersect(box, shadow::volumeFromViewProj(cam.viewProj())));
      }
    sumCulled += cam.culled;
  }
  // The first cascade (under 3 m deep) holds the ground and the post 4 m ahead, not the far ones.
  CHECK(set.cameras[0].casters[0]);
  CHECK_FALSE(set.cameras[0].casters[scene.boxes.size() - 1]);
  CHECK(set.cameras[0].culled >= 10);
  CHECK(sumCulled > 4 * set.culled);  // per cascade, more than the union leaves out

  // Off: every cascade draws the union, and leaves out only what the union does.
  o.cullPerCascade = false;
  const shadow::CascadeSet all = shadow::fitCascades(sun, scene.get(), viewer(), o);
  for (const shadow::LightCamera& cam : all.cameras) {
    CHECK(cam.casters == all.casters);
    CHECK(cam.culled == all.culled);
  }
  CHECK(all.casters == set.casters);
}

TEST_CASE("cascades: a split scheme that does not give count + 1 increasing distances gives no cascades") {
  const Ground g;
  shadow::CascadeOptions o;
  o.count = 3;
  o.fit.mapSize = 512;
  o.splitter = [](double, double, int, double) { return std::vector<double>{}; };  // an untouched stub
  shadow::CascadeSet set = shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o);
  CHECK(set.cameras.empty());
  CHECK(set.problem == "the split scheme gave 0 distances, 4 wanted");
  o.splitter = [](double zn, double zf, int, double) { return std::vector<double>{zn, 5.0, 3.0, zf}; };
  set = shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o);
  CHECK(set.cameras.empty());
  CHECK(set.problem == "the split distances are not finite and increasing at 2");
  o.splitter = [](double, double zf, int, double) { return std::vector<double>{0.5, 2.0, 4.0, zf}; };
  CHECK(shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o).problem ==
        "the splits do not run from the near distance to the far one");
  o.splitter = [](double zn, double zf, int n, double l) { return shadow::cascadeSplits(zn, zf, n, l); };
  set = shadow::fitCascades({0, -1, 0}, g.get(), viewer(), o);
  CHECK(set.problem.empty());
  CHECK(set.cameras.size() == 3);
}

TEST_CASE("cascades: a cascade's light volume reaches back toward the light over the whole scene") {
  // A light straight down from the origin, its box 9 to 11 m below it and 2 m wide; the scene
  // reaches 5 m above the light. The depth pass clamps depth: a caster between the light and the
  // near plane still writes the map, so the volume that culls must hold it.
  shadow::LightCamera cam;
  cam.view = shadow::lightViewAlong(glm::vec3(0.0f), {0, -1, 0});
  cam.projection = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 9.0f, 11.0f);
  const Aabb bounds{{-20, -20, -20}, {20, 5, 20}};
  const shadow::ConvexVolume toward = shadow::orthoVolumeToward(cam, bounds);
  const shadow::ConvexVolume box = shadow::volumeFromViewProj(cam.viewProj());
  const shadow::ConvexVolume above = shadow::volumeFromBox({{-0.2f, -3.0f, -0.2f}, {0.2f, -2.0f, 0.2f}});
  CHECK_FALSE(shadow::volumesMayIntersect(above, box));  // nearer than the near plane...
  CHECK(shadow::volumesMayIntersect(above, toward));     // ...but it casts into the map
  const shadow::ConvexVolume aside = shadow::volumeFromBox({{3.0f, -10.0f, 3.0f}, {4.0f, 4.0f, 4.0f}});
  CHECK_FALSE(shadow::volumesMayIntersect(aside, toward));  // beside the map: no texel of it
  const shadow::ConvexVolume below = shadow::volumeFromBox({{-0.2f, -19.0f, -0.2f}, {0.2f, -12.0f, 0.2f}});
  CHECK_FALSE(shadow::volumesMayIntersect(below, toward));  // beyond the far plane: clamped to 1, never written
}

namespace {

glm::dvec3 mapPoint(const glm::dmat4& worldToClip, const glm::dvec3& p) {
  const glm::dvec4 h = worldToClip * glm::dvec4(p, 1.0);
  return glm::dvec3(h) / h.w;
}

}  // namespace

TEST_CASE("cascades: the warp inside each cascade holds its slice's receivers and refines the slice's near end") {
  const Ground g;
  shadow::CascadeOptions o;
  o.count = 4;
  o.lambda = 1.0;
  o.fit.mapSize = 1024;
  const glm::vec3 sun = glm::normalize(glm::vec3(0.6f, -0.8f, 0.0f));  // across the view: LiSPSM warps most
  const shadow::CascadeSet set = shadow::fitCascades(sun, g.get(), viewer(), o);
  const double band = 0.2;
  const std::vector<shadow::CascadeWarp> warps = shadow::warpCascades(set, viewer(), sun, g.boxes, band);
  REQUIRE(warps.size() == 4);
  for (std::size_t k = 0; k < 4; ++k) {
    CAPTURE(k);
    REQUIRE(warps[k].warped);
    CHECK(std::isfinite(warps[k].n));
    CHECK(warps[k].n > 0.0);
    // The slice's points on the view's axis, from where the previous cascade's blend band starts
    // to the slice's far end, are in the warped map (the ground holds the whole axis).
    const double lead = k == 0 ? 0.0 : band * (set.splits[k] - set.splits[k - 1]);
    for (double t : {0.0, 0.5, 1.0}) {
      const double depth = (set.splits[k] - lead) * (1.0 - t) + set.splits[k + 1] * t;
      const glm::dvec3 q = mapPoint(warps[k].worldToClip, {0.0, 2.0, 20.0 - depth});
      CHECK(glm::all(glm::lessThanEqual(glm::abs(q), glm::dvec3(1.0 + 1e-6))));
    }
    // The warp: 10 cm across the view cover more of the map at the slice's near end than at its
    // far end (an orthographic cascade covers the same at both).
    const double zn = 20.0 - set.splits[k], zf = 20.0 - set.splits[k + 1];
    const auto across = [&](const glm::dmat4& m, double z) {
      return glm::length(mapPoint(m, {0.05, 2.0, z}) - mapPoint(m, {-0.05, 2.0, z}));
    };
    const glm::dmat4 ortho(set.cameras[k].viewProj());
    CHECK(across(ortho, zn) == doctest::Approx(across(ortho, zf)).epsilon(1e-4));
    CHECK(across(warps[k].worldToClip, zn) > 1.2 * across(warps[k].worldToClip, zf));
  }
  // Receivers only 40 m ahead and beyond: the near slices cut none and keep their orthographic cameras.
  const std::vector<Aabb> far{{{-50, -1, -50}, {50, 4, -20}}};
  const std::vector<shadow::CascadeWarp> some = shadow::warpCascades(set, viewer(), sun, far, band);
  CHECK_FALSE(some[0].warped);
  CHECK(some[0].worldToClip == glm::dmat4(set.cameras[0].viewProj()));
  CHECK(some[3].warped);
  shadow::CascadeSet broken = set;
  broken.splits.pop_back();
  CHECK_THROWS_AS(shadow::warpCascades(broken, viewer(), sun, g.boxes, band), std::invalid_argument);
}

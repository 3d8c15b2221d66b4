// algorithms/sdsm: the sample-distribution cascades on a ground plane whose depth buffer follows
// from the geometry (each pixel's ray against y = 0): the range of the tiles, a tile's corners, the
// splits over what is on screen, maps that hold every sample of their slice, tighter than the
// slice's own fit, and the fall-back for a frame of sky.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/sdsm.hpp"

using namespace shadowlab;

namespace {

constexpr int kWide = 96, kHigh = 54, kTile = 8;
const glm::vec3 kSun(0.5f, -1.0f, 0.3f);

// A viewer 2 m above the ground at z = 20, looking down 20 degrees along -z: ground from a few
// metres ahead to the scene's end (z = -50), sky above the horizon.
shadow::CascadeViewer viewer(float pitchDegrees = -20.0f) {
  shadow::CascadeViewer v;
  const glm::vec3 eye(0, 2, 20);
  const float p = glm::radians(pitchDegrees);
  v.view = glm::lookAt(eye, eye + glm::vec3(0, std::sin(p), -std::cos(p)), glm::vec3(0, 1, 0));
  v.fovY = glm::radians(60.0f);
  v.aspect = float(kWide) / float(kHigh);
  v.nearZ = 1.0f;
  v.farZ = 200.0f;
  return v;
}

// The ground, in a scene whose bounds reach 30 m up (a tower out of view): a slice's fit covers the
// air up there too, the samples only the ground.
struct Ground {
  std::vector<Aabb> boxes{{{-50, -1, -50}, {50, 0, 50}}};
  std::vector<char> casts{1};
  shadow::CasterBoxes get() const { return {boxes, casts, {{-50, -1, -50}, {50, 30, 50}}}; }
};

// Where pixel (px, py)'s ray meets the ground inside the scene (false: sky), and its view depth;
// with `wall`, a wall 30 m high across the scene at z = 0 hides what lies beyond it.
bool groundHit(const shadow::CascadeViewer& v, double px, double py, glm::dvec3& world, double& depth,
               bool wall = false) {
  const double tanY = std::tan(0.5 * double(v.fovY)), tanX = tanY * double(v.aspect);
  const glm::dvec3 dirView((2.0 * px / kWide - 1.0) * tanX, (2.0 * py / kHigh - 1.0) * tanY, -1.0);
  const glm::dmat4 toWorld = glm::inverse(glm::dmat4(v.view));
  const glm::dvec3 eye(toWorld[3]);
  const glm::dvec3 dir = glm::dvec3(toWorld * glm::dvec4(dirView, 0.0));  // dirView's z is -1: t is the view depth
  double t = dir.y < 0.0 ? -eye.y / dir.y : INFINITY;
  if (wall && dir.z < 0.0) {
    const double tw = -eye.z / dir.z;
    const glm::dvec3 p = eye + tw * dir;
    if (tw < t && std::abs(p.x) <= 50.0 && p.y >= 0.0 && p.y <= 30.0) t = tw;
  }
  if (!std::isfinite(t)) return false;
  world = eye + t * dir;
  depth = t;
  return std::abs(world.x) <= 50.0 && std::abs(world.z) <= 50.0 && t >= v.nearZ && t <= v.farZ;
}

// The depth buffer of the ground reduced to tiles, as the GPU reduction hands it over.
shadow::DepthTiles groundTiles(const shadow::CascadeViewer& v, bool wall = false) {
  shadow::DepthTiles t;
  t.width = (kWide + kTile - 1) / kTile;
  t.height = (kHigh + kTile - 1) / kTile;
  t.tilePixels = kTile;
  t.pixelsWide = kWide;
  t.pixelsHigh = kHigh;
  t.viewer = v;
  t.depths.assign(std::size_t(t.width * t.height), glm::vec2(INFINITY, -INFINITY));
  for (int py = 0; py < kHigh; ++py)
    for (int px = 0; px < kWide; ++px) {
      glm::dvec3 w;
      double d = 0.0;
      if (!groundHit(v, px + 0.5, py + 0.5, w, d, wall)) continue;
      glm::vec2& r = t.depths[std::size_t((py / kTile) * t.width + px / kTile)];
      r = {std::min(r.x, float(d)), std::max(r.y, float(d))};
    }
  return t;
}

bool inMap(const shadow::LightCamera& c, const glm::vec3& p) {
  const glm::vec4 h = c.viewProj() * glm::vec4(p, 1.0f);
  return glm::all(glm::lessThanEqual(glm::abs(glm::vec3(h) / h.w), glm::vec3(1.001f)));
}

}  // namespace

TEST_CASE("sdsm: the depth range of the tiles leaves out those where nothing was drawn") {
  shadow::DepthTiles t;
  t.width = 3;
  t.height = 1;
  t.pixelsWide = 24;
  t.pixelsHigh = 8;
  t.tilePixels = 8;
  t.depths = {{4.0f, 9.0f}, {INFINITY, -INFINITY}, {2.5f, 30.0f}};
  const shadow::DepthRange r = shadow::depthRange(t);
  CHECK(r.tiles == 2);
  CHECK(r.nearest == 2.5);
  CHECK(r.farthest == 30.0);
  t.depths = {{INFINITY, -INFINITY}, {NAN, NAN}, {INFINITY, -INFINITY}};
  CHECK(shadow::depthRange(t).tiles == 0);
  t.depths.pop_back();
  CHECK_THROWS_WITH_AS(shadow::depthRange(t), "depth tiles: 2 depths for 3 x 1 tiles", std::invalid_argument);
}

TEST_CASE("sdsm: a tile's corners project back onto its pixels at its two depths") {
  shadow::DepthTiles t = groundTiles(viewer());
  const glm::mat4 viewProj =
      glm::perspective(t.viewer.fovY, t.viewer.aspect, t.viewer.nearZ, t.viewer.farZ) * t.viewer.view;
  std::vector<glm::vec3> corners;
  const int x = t.width - 1, y = 2;  // the last column: 96 = 12 tiles of 8 exactly; the last row is 6 pixels
  shadow::tileCorners(t, x, y, 5.0, 12.0, corners);
  REQUIRE(corners.size() == 8);
  for (std::size_t k = 0; k < 8; ++k) {
    const glm::vec4 h = viewProj * glm::vec4(corners[k], 1.0f);
    const double px = (h.x / h.w * 0.5 + 0.5) * kWide, py = (h.y / h.w * 0.5 + 0.5) * kHigh;
    CHECK(px == doctest::Approx((k & 1) ? 96.0 : 88.0).epsilon(1e-4));
    CHECK(py == doctest::Approx((k & 2) ? 24.0 : 16.0).epsilon(1e-4));
    CHECK(h.w == doctest::Approx(k < 4 ? 5.0 : 12.0).epsilon(1e-5));  // w is the view depth
  }
  corners.clear();
  shadow::tileCorners(t, 0, t.height - 1, 5.0, 5.0, corners);  // the top row: pixels 48 to 54
  const glm::vec4 top = viewProj * glm::vec4(corners[3], 1.0f);
  CHECK((top.y / top.w * 0.5 + 0.5) * kHigh == doctest::Approx(54.0).epsilon(1e-4));
}

TEST_CASE("sdsm: the splits run over the depths on screen and each map holds every sample of its slice") {
  const Ground g;
  const shadow::CascadeViewer v = viewer();
  const shadow::DepthTiles tiles = groundTiles(v);
  shadow::SdsmOptions o;
  o.cascades.count = 4;
  o.cascades.lambda = 0.75;
  o.cascades.fit.mapSize = 1024;
  o.band = 0.1;
  const shadow::SdsmFit fit = shadow::fitSampleDistribution(kSun, g.get(), v, tiles, o);
  REQUIRE_FALSE(fit.fellBack);
  REQUIRE(fit.set.problem.empty());
  REQUIRE(fit.set.cameras.size() == 4);
  // The ground is first seen 2 / tan(20 + 30 degrees) along the ground ahead; the scene ends 70 m ahead.
  CHECK(fit.range.nearest > 2.0);
  CHECK(fit.range.farthest < 75.0);
  CHECK(fit.set.splits.front() == doctest::Approx(fit.range.nearest * 0.99));
  CHECK(fit.set.splits.back() == doctest::Approx(fit.range.farthest * 1.01));
  // Every pixel's ground point is in the map of its cascade, and of the next one within the band.
  int checked = 0;
  for (int py = 0; py < kHigh; ++py)
    for (int px = 0; px < kWide; ++px) {
      glm::dvec3 w;
      double d = 0.0;
      if (!groundHit(v, px + 0.5, py + 0.5, w, d)) continue;
      const shadow::CascadeBlend b = shadow::cascadeAt(fit.set.splits, d, o.band);
      REQUIRE(b.cascade >= 0);
      CHECK(inMap(fit.set.cameras[std::size_t(b.cascade)], glm::vec3(w)));
      if (b.nextWeight > 0.0) CHECK(inMap(fit.set.cameras[std::size_t(b.cascade) + 1], glm::vec3(w)));
      ++checked;
    }
  CHECK(checked > kWide * kHigh / 3);
  // Fitted to the samples, each cascade's map covers no more than the whole slice's fit over the same
  // splits, and clearly less in all (the slice's fit covers the air up to the scene's top, which the
  // tiles never saw). Without snapping, whose square maps take the longer side: the boxes themselves.
  shadow::SdsmOptions tight = o, loose = o;
  tight.cascades.fit.snap = loose.cascades.fit.snap = false;
  loose.tightFit = false;
  const shadow::SdsmFit a = shadow::fitSampleDistribution(kSun, g.get(), v, tiles, tight);
  const shadow::SdsmFit b = shadow::fitSampleDistribution(kSun, g.get(), v, tiles, loose);
  REQUIRE(a.set.cameras.size() == 4);
  REQUIRE(b.set.cameras.size() == 4);
  // An orthographic projection's x and y scales are 2 / width and 2 / height.
  const auto area = [](const shadow::LightCamera& c) { return 4.0 / (c.projection[0][0] * c.projection[1][1]); };
  double tightArea = 0.0, looseArea = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(area(a.set.cameras[i]) <= area(b.set.cameras[i]) * 1.0001);
    tightArea += area(a.set.cameras[i]);
    looseArea += area(b.set.cameras[i]);
  }
  CHECK(tightArea < looseArea);
  // The practical cascades start at the near plane, 1 m, where nothing is seen before 2 m.
  const shadow::CascadeSet practical = shadow::fitCascades(kSun, g.get(), v, o.cascades);
  CHECK(practical.splits.front() == 1.0);
  CHECK(fit.set.splits.front() > 2.0);
}

TEST_CASE("sdsm: behind a wall that hides the scene's far half, the cascades end at the wall and are finer") {
  // The viewer looks level: the wall at z = 0 is 20 m ahead, the scene's far end 70 m.
  const Ground g;
  const shadow::CascadeViewer v = viewer(-5.0f);
  const shadow::DepthTiles tiles = groundTiles(v, true);
  shadow::SdsmOptions o;
  o.cascades.fit.mapSize = 1024;
  const shadow::SdsmFit fit = shadow::fitSampleDistribution(kSun, g.get(), v, tiles, o);
  REQUIRE(fit.set.cameras.size() == 4);
  CHECK(fit.range.farthest < 21.0);
  CHECK(fit.set.splits.back() < 21.5);
  const shadow::CascadeSet practical = shadow::fitCascades(kSun, g.get(), v, o.cascades);
  REQUIRE(practical.cameras.size() == 4);
  CHECK(practical.splits.back() > 69.0);
  // The same four maps spent on 2-20 m instead of 1-70 m: every cascade's texels finer.
  for (std::size_t i = 0; i < 4; ++i) CHECK(fit.set.cameras[i].texelWorld < practical.cameras[i].texelWorld);
  // And every sample still in its cascade's map.
  for (int py = 0; py < kHigh; ++py)
    for (int px = 0; px < kWide; ++px) {
      glm::dvec3 w;
      double d = 0.0;
      if (!groundHit(v, px + 0.5, py + 0.5, w, d, true)) continue;
      const shadow::CascadeBlend b = shadow::cascadeAt(fit.set.splits, d, o.band);
      REQUIRE(b.cascade >= 0);
      CHECK(inMap(fit.set.cameras[std::size_t(b.cascade)], glm::vec3(w)));
    }
}

TEST_CASE("sdsm: a frame of sky falls back to the practical cascades and says so") {
  const Ground g;
  const shadow::CascadeViewer v = viewer(35.0f);  // looking up: the ground is below the frame
  const shadow::DepthTiles tiles = groundTiles(v);
  REQUIRE(shadow::depthRange(tiles).tiles == 0);
  shadow::SdsmOptions o;
  const shadow::SdsmFit fit = shadow::fitSampleDistribution({0.0f, -1.0f, 0.0f}, g.get(), v, tiles, o);
  CHECK(fit.fellBack);
  const shadow::CascadeSet practical = shadow::fitCascades({0.0f, -1.0f, 0.0f}, g.get(), v, o.cascades);
  CHECK(fit.set.splits == practical.splits);
  // A student's split scheme that breaks the rules gives no cascades, with why, here too.
  o.cascades.splitter = [](double, double, int, double) { return std::vector<double>{1.0, 2.0}; };
  const shadow::SdsmFit bad =
      shadow::fitSampleDistribution({0.0f, -1.0f, 0.0f}, g.get(), viewer(), groundTiles(viewer()), o);
  CHECK(bad.set.cameras.empty());
  CHECK(bad.set.problem == "the split scheme gave 2 distances, 5 wanted");
}

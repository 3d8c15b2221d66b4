// Ground truth (Embree) against scenes whose shadows are known in closed form.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "measure/ground_truth.hpp"
#include "test_measure_fixtures.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;
using shadowlab::measure::test::addObject;
using shadowlab::measure::test::horizontalQuad;
using shadowlab::measure::test::plainMaterial;
using shadowlab::measure::test::uvSphere;

namespace {

constexpr double kPi = 3.14159265358979323846;

// An orthographic top-down view of the ground y = 0 over [-half, half]^2: pixel centres at
// x = -half + (i + 0.5) * step, z = -half + (j + 0.5) * step (row j = 0 on top), normals +y.
SurfaceBuffer groundView(int size, float half) {
  SurfaceBuffer s(size, size);
  float step = 2 * half / size;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) s.set(i, j, {-half + (i + 0.5f) * step, 0, -half + (j + 0.5f) * step}, {0, 1, 0});
  return s;
}

// The lecture's visible fraction of a disk of radius R behind a straight edge at signed offset a.
double aFrac(double a, double R) {
  double t = a / R;
  return 0.5 + (std::sqrt(1 - t * t) * t + std::asin(t)) / kPi;
}

}  // namespace

TEST_CASE("measure.ground_truth: a sphere over a plane casts the tangent-cone disk of a point light") {
  // Light at height H above the sphere's centre (height h, radius rho). The shadow is the section of
  // the cone tangent to the sphere: half-angle alpha with sin(alpha) = rho / (H - h), so the disk on
  // y = 0 has radius r = H tan(alpha) = H rho / sqrt((H - h)^2 - rho^2).
  const float H = 6, h = 2, rho = 1;
  const int segments = 48, rings = 24;
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-10, 10, -10, 10, 0));
  addObject(scene, uvSphere({0, h, 0}, rho, segments, rings));
  GroundTruth truth(scene);

  // The tessellation is inscribed: every face lies between the sphere and the concentric sphere of
  // radius rho cos(c), c the largest angular circumradius of a face (at most the half-diagonal of a
  // (2 pi / segments) x (pi / rings) patch).
  double c = std::hypot(kPi / segments, kPi / (2 * rings));
  double rhoIn = rho * std::cos(c);
  double rOut = H * rho / std::sqrt((H - h) * (H - h) - rho * rho);
  double rIn = H * rhoIn / std::sqrt((H - h) * (H - h) - rhoIn * rhoIn);

  const int size = 64;
  const float half = 3;
  SurfaceBuffer view = groundView(size, half);
  Light light;
  light.kind = LightKind::Point;
  light.position = {0, H, 0};
  ImageF vis = truth.hardVisibility(view, light);
  REQUIRE(vis.width == size);
  REQUIRE(vis.height == size);
  int shadowed = 0, inBand = 0, wrong = 0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      glm::vec3 p = view.position[view.index(i, j)];
      double d = std::hypot(p.x, p.z);
      float v = vis.at(i, j);
      CHECK((v == 0.0f || v == 1.0f));  // every ground pixel faces the light
      if (v == 0.0f) ++shadowed;
      if (d < rIn - 1e-3) wrong += v != 0.0f;
      else if (d > rOut + 1e-3) wrong += v != 1.0f;
      else ++inBand;
    }
  CHECK(wrong == 0);
  // The disk holds pi r^2 / step^2 pixel centres, give or take its band.
  double step = 2.0 * half / size;
  CHECK(shadowed >= int(kPi * rIn * rIn / (step * step)) - inBand);
  CHECK(shadowed <= int(kPi * rOut * rOut / (step * step)) + inBand);
  CHECK(inBand < size);  // the band is a thin ring, not a large part of the view
  CHECK(shadowed > 500);
  CHECK(truth.lastQueryMs() >= 0.0);
}

TEST_CASE("measure.ground_truth: a directional light casts the sphere's silhouette disk straight down") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-10, 10, -10, 10, 0));
  addObject(scene, uvSphere({0, 2, 0}, 1, 48, 24));
  GroundTruth truth(scene);
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = {0, -1, 0};
  SurfaceBuffer view = groundView(48, 2);
  ImageF vis = truth.hardVisibility(view, sun);
  double rIn = std::cos(std::hypot(kPi / 48, kPi / 48));
  int wrong = 0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 48; ++i) {
      glm::vec3 p = view.position[view.index(i, j)];
      double d = std::hypot(p.x, p.z);
      if (d < rIn - 1e-3) wrong += vis.at(i, j) != 0.0f;
      else if (d > 1 + 1e-3) wrong += vis.at(i, j) != 1.0f;
    }
  CHECK(wrong == 0);
}

TEST_CASE("measure.ground_truth: back-facing, out-of-cone and background pixels are marked apart") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-1, 1, -1, 1, 3));
  GroundTruth truth(scene);
  SurfaceBuffer view(4, 1);
  view.set(0, 0, {0, 0, 0}, {0, 1, 0});   // under the occluder
  view.set(1, 0, {0, 0, 0}, {0, -1, 0});  // facing away
  view.set(2, 0, {5, 0, 0}, {0, 1, 0});   // open sky
  // pixel 3 stays background
  Light light;
  light.kind = LightKind::Point;
  light.position = {0, 6, 0};
  ImageF vis = truth.hardVisibility(view, light);
  CHECK(vis.at(0, 0) == 0.0f);
  CHECK(vis.at(1, 0) == kNotFacing);
  CHECK(vis.at(2, 0) == 1.0f);
  CHECK(vis.at(3, 0) == kBackground);

  // A spot light pointing down with a 0.5 rad outer cone: (5,0,0) is atan(5/6) = 0.69 rad off-axis.
  light.kind = LightKind::Spot;
  light.direction = {0, -1, 0};
  light.spotOuter = 0.5f;
  vis = truth.hardVisibility(view, light);
  CHECK(vis.at(0, 0) == 0.0f);
  CHECK(vis.at(2, 0) == kNotFacing);
  light.spotOuter = 0.8f;
  vis = truth.hardVisibility(view, light);
  CHECK(vis.at(2, 0) == 1.0f);
}

TEST_CASE("measure.ground_truth: a covered pixel with a non-finite position or normal is background, not a ray") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-1, 1, -1, 1, 3));
  GroundTruth truth(scene);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  SurfaceBuffer view(3, 1);
  view.set(0, 0, {nan, 0, 0}, {0, 1, 0});  // what the benchmark's floor shader left in the read-back
  view.set(1, 0, {0, 0, 0}, {0, inf, 0});
  view.set(2, 0, {5, 0, 0}, {0, 1, 0});  // open sky, traced as ever
  Light light;
  light.kind = LightKind::Point;
  light.position = {0, 6, 0};
  light.area = AreaShape::Sphere;
  light.radius = 0.5f;
  for (const ImageF& vis : {truth.hardVisibility(view, light), truth.softVisibility(view, light, 16, 1)}) {
    CHECK(vis.at(0, 0) == kBackground);
    CHECK(vis.at(1, 0) == kBackground);
    CHECK(vis.at(2, 0) == 1.0f);
  }
}

TEST_CASE("measure.ground_truth: a spherical light over a straight edge follows the lecture's A_frac") {
  // Occluder: the half-plane x < 0 at height h (a large quad). Light: sphere of radius R centred at
  // (0, H, 0). From a receiver P = (x, 0, z) the edge and P span a plane with normal ~ (h, x, 0); the
  // light's centre lies at signed distance a = x (H - h) / sqrt(h^2 + x^2) from it, on the visible
  // side when a > 0. Seen from P the sphere is a disk of radius R (to O((R/D)^2)) cut by that plane
  // at a: the visible fraction is A_frac(a). Inverting, x = a h / sqrt((H - h)^2 - a^2).
  const float H = 10, h = 2, R = 0.25f;
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-60, 0, -60, 60, h));
  GroundTruth truth(scene);
  Light light;
  light.kind = LightKind::Point;
  light.position = {0, H, 0};
  light.area = AreaShape::Sphere;
  light.radius = R;

  const double ratios[] = {-0.95, -0.7, -0.4, -0.1, 0.0, 0.2, 0.5, 0.8, 0.97};
  const int columns = int(std::size(ratios)), rows = 8;
  SurfaceBuffer view(columns, rows);
  for (int i = 0; i < columns; ++i) {
    double a = ratios[i] * R;
    double x = a * h / std::sqrt((H - h) * (H - h) - a * a);
    for (int j = 0; j < rows; ++j) view.set(i, j, {float(x), 0, -1.0f + 0.25f * j}, {0, 1, 0});
  }
  ImageF vis = truth.softVisibility(view, light, 256, shadowlab::test::seedFor("afrac"));
  for (int i = 0; i < columns; ++i) {
    double mean = 0;
    for (int j = 0; j < rows; ++j) mean += vis.at(i, j);
    mean /= rows;
    CAPTURE(ratios[i]);
    CHECK(std::abs(mean - aFrac(ratios[i] * R, R)) < 0.01);
  }
  // The linear approximation (1 + a/R) / 2 is within 7% of it, as the lecture says: check the
  // formula we test against is the lecture's, not the linear one, where they differ most.
  CHECK(std::abs(aFrac(0.5 * R, R) - 0.75) > 0.03);
}

TEST_CASE("measure.ground_truth: a rectangular light over a straight edge is visible in proportion") {
  // Rectangle 2 x 1 at height H facing down, first edge along x. The edge at height h hides the
  // light's points with x < x_e = x_P (1 - H / h); the visible fraction is (1 - x_e) / 2.
  const float H = 10, h = 2;
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-60, 0, -60, 60, h));
  GroundTruth truth(scene);
  Light light;
  light.kind = LightKind::Spot;
  light.spotOuter = 1.5f;
  light.position = {0, H, 0};
  light.direction = {0, -1, 0};
  light.area = AreaShape::Rectangle;
  light.size = {2, 1};
  light.tangent = {1, 0, 0};
  const double edges[] = {-0.75, -0.25, 0.0, 0.5, 0.9};
  const int rows = 8;  // receivers along the edge see the same fraction: average out the jitter
  SurfaceBuffer view(int(std::size(edges)), rows);
  for (int i = 0; i < view.width; ++i)
    for (int j = 0; j < rows; ++j) view.set(i, j, {float(edges[i] / (1 - H / h)), 0, -1.0f + 0.25f * j}, {0, 1, 0});
  ImageF vis = truth.softVisibility(view, light, 400, shadowlab::test::seedFor("rect"));
  for (int i = 0; i < view.width; ++i) {
    double mean = 0;
    for (int j = 0; j < rows; ++j) mean += vis.at(i, j);
    mean /= rows;
    CAPTURE(edges[i]);
    CHECK(std::abs(mean - (1 - edges[i]) / 2) < 0.01);
  }
}

TEST_CASE("measure.ground_truth: an alpha-tested card lets light through exactly where alpha < cutoff") {
  // Card: the square [0,4]^2 at y = 1 with uv = (x, z) / 4 and a 4 x 4 texture, so texel (col, row)
  // covers x in [col, col + 1), z in [row, row + 1). Alpha 100 or 160 around a cutoff of 127.5:
  // bilinear filtering 0.2 texels from a texel centre still stays on the texel's side of the cutoff.
  Image8 texture;
  texture.width = 4;
  texture.height = 4;
  texture.channels = 4;
  texture.data.assign(4 * 4 * 4, 255);
  auto opaque = [](int col, int row) { return (col * 3 + row * row) % 4 < 2; };  // irregular on purpose
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) texture.at(col, row)[3] = opaque(col, row) ? 160 : 100;

  Scene scene;
  Material card = plainMaterial();
  card.name = "leaves";
  card.texture = "leaves.png";
  card.alphaCutoff = 0.5f;
  card.twoSided = true;
  scene.materials.push_back(plainMaterial());
  scene.materials.push_back(card);
  addObject(scene, horizontalQuad(-10, 10, -10, 10, 0));
  addObject(scene, horizontalQuad(0, 4, 0, 4, 1), 1);
  GroundTruth truth(scene, std::map<std::string, Image8>{{"leaves.png", texture}});

  const float offsets[] = {-0.2f, 0.0f, 0.2f};
  SurfaceBuffer view(4 * 3, 4 * 3);
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          view.set(col * 3 + a, row * 3 + b, {col + 0.5f + offsets[a], 0, row + 0.5f + offsets[b]}, {0, 1, 0});
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = {0, -1, 0};
  ImageF vis = truth.hardVisibility(view, sun);
  int holes = 0;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          CAPTURE(col);
          CAPTURE(row);
          CHECK(vis.at(col * 3 + a, row * 3 + b) == (opaque(col, row) ? 0.0f : 1.0f));
          holes += !opaque(col, row);
        }
  CHECK(holes > 0);
  CHECK(holes < 16 * 9);

  // Soft rays (packets through the same filter) from a tiny sphere high above agree: a ray to
  // (2, 50, 2) crosses the card at most 2/50 texel off the receiver, still on the same texel's side.
  Light tiny;
  tiny.position = {2, 50, 2};
  tiny.area = AreaShape::Sphere;
  tiny.radius = 0.01f;
  ImageF soft = truth.softVisibility(view, tiny, 16, 3);
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) CHECK(soft.at(col * 3 + a, row * 3 + b) == (opaque(col, row) ? 0.0f : 1.0f));

  // The same card without alpha testing blocks everywhere.
  scene.materials[1].alphaCutoff = 0.0f;
  truth.rebuild(scene);
  vis = truth.hardVisibility(view, sun);
  for (float v : vis.data) CHECK(v == 0.0f);

  // An alpha-tested material whose texture cannot be found is an error naming it.
  scene.materials[1].alphaCutoff = 0.5f;
  scene.materials[1].texture = "missing.png";
  CHECK_THROWS_WITH_AS(GroundTruth(scene, std::map<std::string, Image8>{{"leaves.png", texture}}),
                       doctest::Contains("missing.png"), std::invalid_argument);
  // A rebuild that fails keeps the previous BVH (the opaque card) answering.
  CHECK_THROWS_AS(truth.rebuild(scene), std::invalid_argument);
  CHECK(truth.buildCount() == 2);
  vis = truth.hardVisibility(view, sun);
  for (float v : vis.data) CHECK(v == 0.0f);
}

TEST_CASE("measure.ground_truth: the BVH is rebuilt only when the scene changed") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-1, 1, -1, 1, 2));
  GroundTruth truth(scene);
  CHECK(truth.buildCount() == 1);
  CHECK(truth.triangleCount() == 2);
  SurfaceBuffer view(1, 1);
  view.set(0, 0, {0, 0, 0}, {0, 1, 0});
  Light light;
  light.position = {0, 5, 0};
  CHECK(truth.hardVisibility(view, light).at(0, 0) == 0.0f);
  light.area = AreaShape::Sphere;
  light.radius = 0.1f;
  truth.softVisibility(view, light, 4, 1);
  CHECK(truth.buildCount() == 1);

  CHECK(truth.update(scene, 7));
  CHECK(truth.buildCount() == 2);
  // Moving the occluder away does nothing until the ground truth is told...
  scene.objects[0].model = glm::mat4(1.0f);
  scene.objects[0].model[3] = glm::vec4(10, 0, 0, 1);
  CHECK_FALSE(truth.update(scene, 7));
  CHECK(truth.buildCount() == 2);
  CHECK(truth.hardVisibility(view, light).at(0, 0) == 0.0f);
  // ...and takes effect once it is.
  CHECK(truth.update(scene, 8));
  CHECK(truth.buildCount() == 3);
  CHECK(truth.hardVisibility(view, light).at(0, 0) == 1.0f);
}

TEST_CASE("measure.ground_truth: soft visibility is deterministic for a seed, whatever the threads") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-60, 0, -60, 60, 2));
  Light light;
  light.position = {0, 10, 0};
  light.area = AreaShape::Sphere;
  light.radius = 0.5f;
  SurfaceBuffer view(16, 8);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 16; ++i) view.set(i, j, {-0.2f + 0.025f * i, 0, 0.1f * j}, {0, 1, 0});
  GroundTruthOptions one;
  one.threads = 1;
  GroundTruthOptions two;
  two.threads = 2;
  GroundTruth a(scene, TextureLookup{}, one), b(scene, TextureLookup{}, two);
  ImageF va = a.softVisibility(view, light, 16, 99), vb = b.softVisibility(view, light, 16, 99);
  CHECK(va.data == vb.data);
  bool partial = false;
  for (float v : va.data) partial = partial || (v > 0.0f && v < 1.0f);
  CHECK(partial);  // the view crosses the penumbra
}

TEST_CASE("measure.ground_truth: bad input throws naming the value") {
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-1, 1, -1, 1, 2));
  GroundTruth truth(scene);
  SurfaceBuffer view(2, 2);
  Light light;
  light.area = AreaShape::Sphere;
  CHECK_THROWS_WITH_AS(truth.softVisibility(view, light, 0, 1), doctest::Contains("samples 0"), std::invalid_argument);
  Light unknown;
  unknown.kind = static_cast<LightKind>(7);
  CHECK_THROWS_WITH_AS(truth.hardVisibility(view, unknown), doctest::Contains("7"), std::invalid_argument);
  Light pointOnly;  // no area shape: nothing to sample
  CHECK_THROWS_AS(truth.softVisibility(view, pointOnly, 4, 1), std::invalid_argument);
  Light sun;
  sun.kind = LightKind::Directional;
  sun.area = AreaShape::Sphere;
  CHECK_THROWS_WITH_AS(truth.softVisibility(view, sun, 4, 1), doctest::Contains("Directional"), std::invalid_argument);
  SurfaceBuffer broken(2, 2);
  broken.normal.pop_back();
  CHECK_THROWS_WITH_AS(truth.hardVisibility(broken, Light{}), doctest::Contains("normal 3"), std::invalid_argument);
  CHECK_THROWS_AS(downsample(view, 0), std::invalid_argument);
  ImageF pos, nrm;
  pos.width = 2;
  pos.height = 2;
  pos.channels = 4;
  pos.data.assign(16, 0.0f);
  nrm.width = 3;
  nrm.height = 2;
  nrm.channels = 4;
  nrm.data.assign(24, 0.0f);
  CHECK_THROWS_WITH_AS(surfaceFromImages(pos, nrm), doctest::Contains("3x2"), std::invalid_argument);
}

TEST_CASE("measure.ground_truth: read-backs and downsampling keep pixels where they were") {
  ImageF pos, nrm;
  pos.width = nrm.width = 4;
  pos.height = nrm.height = 2;
  pos.channels = nrm.channels = 4;
  pos.data.assign(32, 0.0f);
  nrm.data.assign(32, 0.0f);
  pos.at(3, 1, 0) = 1;
  pos.at(3, 1, 1) = 2;
  pos.at(3, 1, 2) = 3;
  pos.at(3, 1, 3) = 1;
  nrm.at(3, 1, 1) = 2;  // renormalised to (0,1,0)
  SurfaceBuffer s = surfaceFromImages(pos, nrm);
  CHECK(s.covered[s.index(3, 1)] == 1);
  CHECK(s.position[s.index(3, 1)] == glm::vec3(1, 2, 3));
  CHECK(s.normal[s.index(3, 1)] == glm::vec3(0, 1, 0));
  int covered = 0;
  for (auto c : s.covered) covered += c;
  CHECK(covered == 1);
  SurfaceBuffer half = downsample(s, 2);
  CHECK(half.width == 2);
  CHECK(half.height == 1);
  CHECK(half.covered[half.index(1, 0)] == 1);  // block (1,0) samples pixel (3,1)
  CHECK(half.position[half.index(1, 0)] == glm::vec3(1, 2, 3));
}

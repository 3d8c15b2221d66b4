// The lecture's penumbra half-width r = d / (n.L) * R / D against the Embree sphere-light reference
// (lesson 05's goal: the measured penumbra width along the test edge within 10 % of the formula, or
// the reason it is not). Across a straight edge the reference's visibility runs from 0 to 1 over the
// penumbra as A_frac(x / r); the width between visibility 0.05 and 0.95 is r times
// 2 A_frac^-1(0.95). Rays: 4096 per point, so the noise moves a crossing by under 1 % of r.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "algorithms/soft_shadows.hpp"
#include "core/scene_gen.hpp"
#include "measure/ground_truth.hpp"
#include "test_measure_fixtures.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;
using namespace shadowlab::measure::test;

namespace {

Light sphereLight(glm::vec3 position, float radius) {
  Light l;
  l.kind = LightKind::Point;
  l.position = position;
  l.area = AreaShape::Sphere;
  l.radius = radius;
  return l;
}

struct Crossings {
  float at05 = 0, at50 = 0, at95 = 0;  // distance along the line where visibility crosses each level
};

// Visibility of the reference along `points` ground points from `from` to `to` (normal +y), and
// where it first crosses 0.05, 0.5 and 0.95 going from the umbra side (`from`) outward.
Crossings measureAcross(const GroundTruth& truth, const Light& light, glm::vec3 from, glm::vec3 to, int points) {
  SurfaceBuffer line(points, 1);
  for (int i = 0; i < points; ++i) line.set(i, 0, glm::mix(from, to, float(i) / float(points - 1)), {0, 1, 0});
  const ImageF v = truth.softVisibility(line, light, 4096, 7);
  const float length = glm::length(to - from);
  Crossings c;
  float* slot[] = {&c.at05, &c.at50, &c.at95};
  const float levels[] = {0.05f, 0.5f, 0.95f};
  for (int l = 0; l < 3; ++l) {
    *slot[l] = -1;
    for (int i = 1; i < points && *slot[l] < 0; ++i) {
      const float a = v.at(i - 1, 0), b = v.at(i, 0);
      if (a < levels[l] && b >= levels[l])
        *slot[l] = length * (float(i - 1) + (levels[l] - a) / (b - a)) / float(points - 1);
    }
  }
  return c;
}

// The width between 0.05 and 0.95 that A_frac(x / r) predicts for a half-width r.
float predictedWidth(float r) { return 2.0f * r * soft::visibleFractionInverse(0.95f); }

// Measures the penumbra of the caster point `c` across the direction `across` (unit, in the ground
// plane, pointing out of the umbra) and returns measured / predicted width.
float widthRatio(const GroundTruth& truth, const Light& light, glm::vec3 c, glm::vec3 across, float* formula) {
  const soft::PenumbraPoint p = soft::penumbraOnPlane(light.position, light.radius, c, {0, 1, 0, 0});
  REQUIRE(p.valid);
  *formula = p.halfWidth;
  const Crossings x =
      measureAcross(truth, light, p.centre - 3.0f * p.halfWidth * across, p.centre + 3.0f * p.halfWidth * across, 601);
  REQUIRE(x.at05 > 0);
  REQUIRE(x.at95 > 0);
  // The centre line: visibility 1/2 where the ray from the light's centre grazes the edge.
  CHECK(std::abs(x.at50 - 3.0f * p.halfWidth) < 0.05f * p.halfWidth);
  return (x.at95 - x.at05) / predictedWidth(p.halfWidth);
}

}  // namespace

TEST_CASE("soft truth: the formula's width holds for an edge across the plane of incidence") {
  // A plate x < 3 at height 2, edge along z; light (R 0.5) at (0, 10, 0). The plane of incidence
  // at the edge's shadow is the xy plane, across the edge. r = sqrt(73) R / 32 = 0.1335; the exact
  // footprint of the cone of half-angle asin(R / D) from the edge point is 0.1311 inside and 0.1371
  // outside (mean 0.1341, +0.5 %).
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-40, 3, -40, 40, 2));
  const GroundTruth truth(scene);
  const Light light = sphereLight({0, 10, 0}, 0.5f);
  float r = 0;
  const float ratio = widthRatio(truth, light, {3, 2, 0}, {1, 0, 0}, &r);
  CHECK(r == doctest::Approx(std::sqrt(73.0) * 0.5 / 32));
  MESSAGE("edge across incidence: r = " << r << " m, measured / predicted width = " << ratio);
  CHECK(std::abs(ratio - 1.0f) < 0.10f);
  CHECK(std::abs(ratio - 1.0f) < 0.03f);  // in fact within a few %: the small-angle R / D and noise
}

TEST_CASE("soft truth: the formula over-states by 1 / (n.L) for an edge in the plane of incidence") {
  // A plate z < 0 at height 2, edge along x; light (R 0.5) at (-8, 6, 0). Across the edge (along z)
  // the light's centre is a = 2z from the plane through the edge and the receiver (z, small), so the
  // true half-width is R / 2 = 0.25, while d / (n.L) * R / D = sqrt(80) R / 8 = 0.559: the
  // 1 / (n.L) = 2.24 stretch happens along the plane of incidence, here along the edge, not across it.
  Scene scene;
  scene.materials.push_back(plainMaterial());
  addObject(scene, horizontalQuad(-40, 40, -40, 0, 2));
  const GroundTruth truth(scene);
  const Light light = sphereLight({-8, 6, 0}, 0.5f);
  float r = 0;
  const float ratio = widthRatio(truth, light, {0, 2, 0}, {0, 0, 1}, &r);
  const soft::PenumbraPoint p = soft::penumbraOnPlane(light.position, light.radius, {0, 2, 0}, {0, 1, 0, 0});
  MESSAGE("edge along incidence: r = " << r << " m, n.L = " << p.nDotL << ", measured / predicted = " << ratio);
  CHECK(r == doctest::Approx(std::sqrt(80.0) * 0.5 / 8));
  CHECK(ratio < 0.9f);                                 // the formula is NOT within 10 % here
  CHECK(std::abs(ratio - p.nDotL) < 0.03f * p.nDotL);  // and the reason: it is off by n.L
}

TEST_CASE("soft truth: the showcase box's test edge, lit as lesson 05 lights it") {
  // Lesson 05's default: the showcase (seed 1, 30k triangles), light0 a sphere of radius 0.5 at
  // (0.96, 7, -1.62). The test edge is the box's top edge 11 (soft::boxEdges), whose plane of
  // incidence the light was placed across; the shadow of its middle falls on the open ground.
  const Scene scene = makeScene("showcase", 1, 30000);
  const SceneObject* box = nullptr;
  for (const auto& o : scene.objects)
    if (o.name == "box") box = &o;
  REQUIRE(box);
  const auto edge = soft::boxEdges(box->model, glm::vec3(1.0f))[11];
  const GroundTruth truth(scene);
  const Light light = sphereLight({0.96f, 7.0f, -1.62f}, 0.5f);
  const glm::vec3 mid = 0.5f * (edge[0] + edge[1]);
  const glm::vec3 interior = glm::vec3(box->model * glm::vec4(0, 0, 0, 1));
  const auto samples =
      soft::penumbraAlongEdge(light.position, light.radius, edge[0], edge[1], interior, {0, 1, 0, 0}, 3);
  REQUIRE(samples.size() == 3);
  const glm::vec3 across = glm::normalize(samples[1].outer - samples[1].inner);
  // How far the edge is from perpendicular to the plane of incidence (0: the formula's best case).
  const glm::vec3 along = glm::normalize(edge[1] - edge[0]);
  const glm::vec3 toLight = glm::normalize(light.position - samples[1].centre);
  const float skew = std::abs(glm::dot(along, glm::normalize(glm::vec3(toLight.x, 0, toLight.z))));
  float r = 0;
  const float ratio = widthRatio(truth, light, mid, across, &r);
  MESSAGE("showcase edge 11: r = " << r << " m, |cos| between edge and incidence " << skew
                                   << ", measured / predicted = " << ratio);
  CHECK(std::abs(ratio - 1.0f) < 0.10f);
}

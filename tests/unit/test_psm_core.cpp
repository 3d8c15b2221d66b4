// Unit tests for common/algorithms/psm: conventions, clipping, cone, cameras (hand-derived values).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/clipping.hpp"
#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/enclosing_cone.hpp"
#include "algorithms/psm/psm_camera.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::psm;

namespace {
// Camera at the origin looking down -z, fovY 90, aspect 1, n = 1, f = 3 (see ex08's hand cases).
CameraFrustum handCamera() { return makeCamera(glm::dmat4(1.0), std::numbers::pi / 2, 1.0, 1.0, 3.0); }
Aabb box(glm::vec3 lo, glm::vec3 hi) {
  Aabb b;
  b.min = lo;
  b.max = hi;
  return b;
}
}  // namespace

TEST_CASE("psm conventions: perspectiveGL is GL's matrix and rejects bad values by name") {
  const glm::dmat4 p = perspectiveGL(std::numbers::pi / 2, 2.0, 1.0, 3.0);
  CHECK(p[0][0] == doctest::Approx(0.5));
  CHECK(p[1][1] == doctest::Approx(1.0));
  CHECK(p[2][2] == doctest::Approx(-2.0));
  CHECK(p[3][2] == doctest::Approx(-3.0));
  CHECK(p[2][3] == doctest::Approx(-1.0));
  CHECK_THROWS_WITH_AS(perspectiveGL(1.0, 1.0, 0.0, 3.0), doctest::Contains("zNear"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(perspectiveGL(1.0, 1.0, 2.0, 2.0), doctest::Contains("zFar"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(perspectiveGL(std::nan(""), 1.0, 1.0, 2.0), doctest::Contains("fovY"), std::invalid_argument);
  CHECK_THROWS_AS(perspectiveGL(1.0, -1.0, 1.0, 2.0), std::invalid_argument);
}

TEST_CASE("psm conventions: lights classified in front, behind, direction") {
  const CameraFrustum c = handCamera();
  PostProjectiveLight l = toPostProjective(c.viewProj, {0, 0, -2, 1});
  CHECK(l.kind == PostLightKind::InFront);
  CHECK(l.position.z == doctest::Approx(0.5));
  l = toPostProjective(c.viewProj, {0, 0, 1, 0});  // directional, from behind
  CHECK(l.kind == PostLightKind::Behind);
  CHECK(l.position.z == doctest::Approx(2.0));  // (f+n)/(f-n)
  l = toPostProjective(c.viewProj, {0, 1, 0, 0});
  CHECK(l.kind == PostLightKind::Direction);
  CHECK(l.direction.y == doctest::Approx(1.0));
  CHECK_THROWS_AS(toPostProjective(c.viewProj, {0, 0, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(toPostProjective(c.viewProj, {std::nan(""), 0, 0, 1}), std::invalid_argument);
  Light d;
  d.kind = LightKind::Directional;
  d.direction = {0, -2, 0};
  CHECK(homogeneousLight(d) == glm::dvec4(0, 1, 0, 0));
}

TEST_CASE("psm conventions: the [0,1] remap maps NDC depth -1 -> 0 and 1 -> 1") {
  const glm::dmat4 r = depthRangeRemap(DepthRange::ZeroToOne);
  const glm::dvec4 a = r * glm::dvec4(0, 0, -2, 2), b = r * glm::dvec4(0, 0, 3, 3);
  CHECK(a.z / a.w == doctest::Approx(0.0));
  CHECK(b.z / b.w == doctest::Approx(1.0));
}

TEST_CASE("psm clipping: a box inside the frustum keeps its 8 corners, one outside gives none") {
  const CameraFrustum c = handCamera();
  const Frustum f = frustumFromViewProj(c.viewProj, c.invViewProj);
  std::vector<glm::dvec3> out;
  clipBoxToFrustum(box({-0.1f, -0.1f, -2.1f}, {0.1f, 0.1f, -1.9f}), f, out);
  CHECK(out.size() == 8);  // wholly inside: its 8 corners
  for (const auto& p : out) CHECK(std::abs(std::abs(p.x) - 0.1) < 1e-6);
  out.clear();
  CHECK(clipBoxToFrustum(box({5, 5, -2}, {6, 6, -1}), f, out) == 0);
  CHECK(clipBoxToFrustum(box({-1, -1, 1}, {1, 1, 2}), f, out) == 0);  // behind the camera
}

TEST_CASE("psm clipping: a huge box yields exactly the frustum's corners") {
  const CameraFrustum c = handCamera();
  const Frustum f = frustumFromViewProj(c.viewProj, c.invViewProj);
  std::vector<glm::dvec3> out;
  clipBoxToFrustum(box({-100, -100, -100}, {100, 100, 100}), f, out);
  REQUIRE(!out.empty());
  // Every output is one of the 8 corners: (+-1, +-1, -1) and (+-3, +-3, -3).
  for (const auto& p : out) {
    const double z = -p.z;
    CHECK((std::abs(z - 1) < 1e-9 || std::abs(z - 3) < 1e-9));
    CHECK(std::abs(std::abs(p.x) - z) < 1e-9);
    CHECK(std::abs(std::abs(p.y) - z) < 1e-9);
  }
}

TEST_CASE("psm clipping: a box across the near plane is cut at z = -1") {
  const CameraFrustum c = handCamera();
  const Frustum f = frustumFromViewProj(c.viewProj, c.invViewProj);
  std::vector<glm::dvec3> out;
  clipBoxToFrustum(box({-0.5f, -0.5f, -1.5f}, {0.5f, 0.5f, 0.5f}), f, out);
  double zMax = -1e9, zMin = 1e9;
  for (const auto& p : out) {
    zMax = std::max(zMax, p.z);
    zMin = std::min(zMin, p.z);
  }
  CHECK(zMax == doctest::Approx(-1.0));
  CHECK(zMin == doctest::Approx(-1.5));
}

TEST_CASE("psm clipping: invalid boxes are rejected by name") {
  const CameraFrustum c = handCamera();
  const Frustum f = frustumFromViewProj(c.viewProj, c.invViewProj);
  std::vector<glm::dvec3> out;
  CHECK_THROWS_WITH_AS(clipBoxToFrustum(box({1, 0, 0}, {0, 1, 1}), f, out), doctest::Contains("min > max"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(clipBoxToFrustum(box({1, 1, 1}, {1, 1, 1}), f, out), doctest::Contains("zero size"),
                       std::invalid_argument);
  CHECK_THROWS_AS(clipBoxToFrustum(box({std::nanf(""), 0, 0}, {1, 1, 1}), f, out), std::invalid_argument);
  CHECK_NOTHROW(clipBoxToFrustum(box({-1, -1, -2}, {1, -1, -1.5f}), f, out));  // flat: a floor tile
}

TEST_CASE("psm cone: hand sets and the hemisphere limit") {
  std::vector<glm::dvec3> d = {{1, 0, 0}, {0, 1, 0}};
  Cone c = smallestEnclosingCone(d);
  CHECK(c.valid);
  CHECK(c.halfAngle == doctest::Approx(std::numbers::pi / 4));
  CHECK(c.axis.x == doctest::Approx(std::sqrt(0.5)));
  d = {{0, 0, 1}};
  c = smallestEnclosingCone(d);
  CHECK(c.halfAngle == doctest::Approx(0.0));
  d = {{1, 0, 0}, {-1, 0, 0}};  // opposite: no open hemisphere holds them
  CHECK_FALSE(smallestEnclosingCone(d).valid);
  d = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}};
  CHECK_FALSE(smallestEnclosingCone(d).valid);
  d = {{0, 0, 0}};
  CHECK_THROWS_AS(smallestEnclosingCone(d), std::invalid_argument);
  d.clear();
  CHECK_FALSE(smallestEnclosingCone(d).valid);
}

namespace {
// Sets of minCount + i % countRange directions around random centres, spread 1e-9 to 0.13 across,
// against the brute force; returns how many sets fit in a hemisphere (the ones compared).
int checkRandomCones(const char* seedName, int sets, int minCount, int countRange) {
  std::mt19937_64 rng(shadowlab::test::seedFor(seedName));
  std::normal_distribution<double> g(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < sets; ++i) {
    const glm::dvec3 centre = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const double spread = std::pow(10.0, -9.0 + 9.0 * (i % 10) / 10.0);
    std::vector<glm::dvec3> d;
    for (int k = 0; k < minCount + i % countRange; ++k)
      d.push_back(centre + spread * glm::dvec3(g(rng), g(rng), g(rng)));
    const Cone brute = smallestEnclosingConeBruteForce(d);
    std::vector<glm::dvec3> copy = d;
    const Cone fast = smallestEnclosingCone(copy);
    if (!brute.valid) continue;
    ++compared;
    CHECK(fast.valid);
    CHECK(std::abs(fast.halfAngle - brute.halfAngle) <= 1e-7 * brute.halfAngle + 1e-15);
  }
  return compared;
}
}  // namespace

TEST_CASE("psm cone: random sets match the brute force, also for 1e-9 rad cones") {
  checkRandomCones("psm cone random", 300, 2, 7);
}

TEST_CASE("psm cone: 16 and more directions (extremes, then the points outside) match the brute force") {
  CHECK(checkRandomCones("psm cone core set", 60, 16, 17) == 60);  // spreads up to 0.13: all in a hemisphere
}

TEST_CASE("psm cone: boundary points the extremes miss still shape the cone") {
  // A ring of 35 directions 0.3 rad around +z, every fifth one pushed out to 0.5 rad (7 outer
  // ones, no two opposite), then 200 directions near the axis: the extremes taken first need not
  // be the outer ones, and the cone is right only if the points outside their ball are refitted.
  std::vector<glm::dvec3> d;
  for (int k = 0; k < 35; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / 35.0, theta = k % 5 == 0 ? 0.5 : 0.3;
    d.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
  }
  for (int k = 0; k < 200; ++k) d.push_back({1e-3 * (k % 7 - 3), 1e-3 * (k % 5 - 2), 1.0});
  std::vector<glm::dvec3> copy = d;
  const Cone c = smallestEnclosingCone(copy);
  CHECK(c.valid);
  CHECK(c.halfAngle == doctest::Approx(0.5).epsilon(1e-12));  // 7 points at 0.5 rad, evenly spread
  CHECK(c.axis.z == doctest::Approx(1.0).epsilon(1e-12));
  // The same cone in every input order.
  for (int r = 0; r < 5; ++r) {
    std::rotate(d.begin(), d.begin() + 37, d.end());
    copy = d;
    CHECK(smallestEnclosingCone(copy).halfAngle == doctest::Approx(0.5).epsilon(1e-12));
  }
}

TEST_CASE("psm cone: thousands of points from an apex (sampled core set) hold every point and are optimal") {
  // Clouds of 400 to 6,000 points around random centres, 1e-9 to 0.13 rad across, a random apex:
  // the path of enclosingConeFrom that starts from a sample and scans the raw directions. Sound:
  // every direction within the half-angle. Optimal: the brute force over the points near the
  // boundary (any cone holding all points holds those) finds no narrower cone. The depth range
  // is exactly the least and greatest dot(p - apex, axis).
  std::mt19937_64 rng(shadowlab::test::seedFor("psm cone sampled"));
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<glm::dvec3> core;
  int compared = 0;
  for (int i = 0; i < 40; ++i) {
    const glm::dvec3 apex(g(rng) * 10.0, g(rng) * 10.0, g(rng) * 10.0);
    const glm::dvec3 centre = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const double spread = std::pow(10.0, -9.0 + 9.0 * (i % 10) / 10.0), dist = std::pow(10.0, 1 + i % 4);
    const int n = 400 + (i * 1531) % 5600;
    std::vector<glm::dvec3> pts;
    for (int k = 0; k < n; ++k) {
      glm::dvec3 dir = centre + spread * glm::dvec3(g(rng), g(rng), g(rng));
      if (i % 3 == 0 && k % 97 == 0) dir = centre + 2.5 * spread * glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
      pts.push_back(apex + dir * dist * (1.0 + 0.5 * std::abs(g(rng))));
    }
    const ConeFit f = enclosingConeFrom(apex, pts, core);
    REQUIRE(f.bad == std::numeric_limits<std::size_t>::max());
    REQUIRE(f.cone.valid);
    double worst = 0.0, lo = 1e300, hi = -1e300;
    std::vector<glm::dvec3> boundary;
    for (const glm::dvec3& p : pts) {
      const glm::dvec3 d = p - apex;
      const double ang = std::atan2(glm::length(glm::cross(f.cone.axis, d)), glm::dot(f.cone.axis, d));
      worst = std::max(worst, ang - f.cone.halfAngle);
      if (ang >= f.cone.halfAngle * (1.0 - 2e-3)) boundary.push_back(d);
      lo = std::min(lo, glm::dot(d, f.cone.axis));
      hi = std::max(hi, glm::dot(d, f.cone.axis));
    }
    CHECK(worst <= 1e-9 * f.cone.halfAngle + 1e-15);
    CHECK(f.minAlong == lo);
    CHECK(f.maxAlong == hi);
    if (boundary.size() > 60) continue;  // the brute force is O(n^4)
    ++compared;
    const Cone brute = smallestEnclosingConeBruteForce(boundary);
    CHECK(std::abs(f.cone.halfAngle - brute.halfAngle) <= 1e-7 * brute.halfAngle + 1e-15);
    const Cone same = smallestEnclosingCone(std::vector<glm::dvec3>(boundary));
    CHECK(std::abs(same.halfAngle - brute.halfAngle) <= 1e-7 * brute.halfAngle + 1e-15);
  }
  CHECK(compared >= 30);
  // A point at the apex, or a NaN one, is reported by index (fitLightCamera: no cone can be aimed).
  std::vector<glm::dvec3> pts(1000, glm::dvec3(0.0, 0.0, -5.0));
  for (std::size_t k = 0; k < pts.size(); ++k) pts[k].x = 1e-3 * double(k % 13);
  pts[613] = glm::dvec3(0.0);
  CHECK(enclosingConeFrom(glm::dvec3(0.0), pts, core).bad == 613);
  pts[613] = glm::dvec3(std::numeric_limits<double>::quiet_NaN());
  CHECK(enclosingConeFrom(glm::dvec3(0.0), pts, core).bad == 613);
  CHECK_THROWS_WITH_AS(smallestEnclosingCone(pts), doctest::Contains("direction 613"), std::invalid_argument);
  pts[613] = glm::dvec3(0.0, 0.0, -5.0);
  CHECK(enclosingConeFrom(glm::dvec3(0.0), pts, core).bad == std::numeric_limits<std::size_t>::max());
}

TEST_CASE("psm cone: among thousands of points a bad one, the widest or one behind is found in every lane") {
  // enclosingConeFrom's scans take four points at a time (two vector registers of two lanes) and
  // hand any four that are not the common case to the scalar code: plant the exception at each
  // place of a four, and in the tail after the last whole four.
  const glm::dvec3 apex(1.0, -2.0, 3.0), axis = glm::normalize(glm::dvec3(0.3, 0.4, -1.0));
  const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0.0, 1.0, 0.0)));
  std::vector<glm::dvec3> cloud;
  const int n = 1003;  // the sample takes every 10th point; 1,000 in fours, then a tail of 3
  for (int k = 0; k < n; ++k) {
    const double t = 0.05 * std::sin(0.37 * k), u = 0.05 * std::cos(1.91 * k);
    cloud.push_back(apex + 10.0 * (axis + t * side + u * glm::cross(axis, side)));
  }
  std::vector<glm::dvec3> core;
  for (std::size_t at : {401u, 402u, 403u, 404u, 405u, 1001u, 1002u}) {
    CAPTURE(at);
    std::vector<glm::dvec3> pts = cloud;
    pts[at] = apex;  // at the light: no direction
    CHECK(enclosingConeFrom(apex, pts, core).bad == at);
    pts[at] = glm::dvec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    CHECK(enclosingConeFrom(apex, pts, core).bad == at);
    // The widest: 0.3 rad off the axis, where the cloud reaches 0.071.
    pts[at] = apex + 10.0 * (axis + std::tan(0.3) * side);
    ConeFit f = enclosingConeFrom(apex, pts, core);
    REQUIRE(f.bad == std::numeric_limits<std::size_t>::max());
    REQUIRE(f.cone.valid);
    double worst = -1.0;
    for (const glm::dvec3& p : pts) {
      const glm::dvec3 d = p - apex;
      worst = std::max(worst, std::atan2(glm::length(glm::cross(f.cone.axis, d)), glm::dot(f.cone.axis, d)));
    }
    CHECK(worst <= f.cone.halfAngle * (1.0 + 1e-12));
    CHECK(f.cone.halfAngle > 0.15);  // the planted point widened it (about (0.3 + 0.07) / 2)
    // Behind the light: no cone under 90 degrees holds it and the cloud.
    pts[at] = apex - 10.0 * axis;
    CHECK_FALSE(enclosingConeFrom(apex, pts, core).cone.valid);
  }
}

TEST_CASE("psm cone: 16 and more directions outside any hemisphere, or one bad, are reported") {
  std::vector<glm::dvec3> d;
  for (int k = 0; k < 30; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / 30.0;
    d.push_back({std::cos(phi), std::sin(phi), 0.1 * (k % 3 - 1)});  // a belt round the sphere
  }
  std::vector<glm::dvec3> copy = d;
  CHECK_FALSE(smallestEnclosingCone(copy).valid);
  d.assign(20, glm::dvec3(0.0, 0.0, 1.0));
  copy = d;
  CHECK(smallestEnclosingCone(copy).halfAngle == doctest::Approx(0.0));  // all the same
  d[17] = glm::dvec3(0.0);
  CHECK_THROWS_WITH_AS(smallestEnclosingCone(d), doctest::Contains("direction 17"), std::invalid_argument);
  d[17] = glm::dvec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0);
  CHECK_THROWS_WITH_AS(smallestEnclosingCone(d), doctest::Contains("direction 17"), std::invalid_argument);
}

TEST_CASE("psm camera: the inverse projection's depth is a / Z, and [0,1] is (1 + a/Z) / 2") {
  const glm::dmat4 m = inverseProjection(1.0, 1.0, 0.5);
  const glm::dmat4 m01 = inverseProjection(1.0, 1.0, 0.5, DepthRange::ZeroToOne);
  for (double Z : {-0.5, -1.0, -7.0, 7.0, 1.0, 0.5}) {
    const glm::dvec4 h = m * glm::dvec4(0, 0, -Z, 1), h01 = m01 * glm::dvec4(0, 0, -Z, 1);
    CHECK(h.z / h.w == doctest::Approx(0.5 / Z));
    CHECK(h01.z / h01.w == doctest::Approx(0.5 * (1 + 0.5 / Z)));
  }
  CHECK_THROWS_WITH_AS(inverseProjection(1.0, 1.0, 0.0), doctest::Contains("a ="), std::invalid_argument);
}

TEST_CASE("psm camera: light behind the camera gets the inverse projection and keeps ray order") {
  const CameraFrustum c = handCamera();
  const std::vector<Aabb> recv = {box({-0.5f, -0.5f, -2.5f}, {0.5f, 0.5f, -1.5f})};
  PsmFitter fitter;
  const glm::dvec4 light(0.3, 1.0, 1.0, 0.0);  // from behind and above: travels along -z
  const PsmFit& fit = fitter.fit(c, light, recv);
  REQUIRE(fit.status == FitStatus::Ok);
  CHECK(fit.light.kind == PostLightKind::Behind);
  CHECK(fit.camera.kind == LightProjection::Inverse);
  const glm::dmat4& M = fit.camera.worldToClip;
  for (const auto& p : fitter.worldKeyPoints()) {
    const glm::dvec4 h = M * glm::dvec4(p, 1.0);
    REQUIRE(h.w > 0);
    CHECK(std::abs(h.x / h.w) <= 1 + 1e-9);
    CHECK(std::abs(h.z / h.w) <= 1 + 1e-9);
  }
  // A caster behind the camera on the ray to a receiver is nearer the light in the map.
  const glm::dvec3 X(0.0, 0.0, -2.0), caster = X + glm::dvec3(light) * 2.5;  // z = 0.5: behind the eye
  const glm::dvec4 hx = M * glm::dvec4(X, 1.0), hc = M * glm::dvec4(caster, 1.0);
  REQUIRE(hc.w > 0);
  CHECK(hc.z / hc.w < hx.z / hx.w);
  CHECK(std::abs(hc.x / hc.w - hx.x / hx.w) < 1e-9);  // same texel: the same light ray
}

TEST_CASE("psm camera: original PSM slides the camera back only for a light behind") {
  const CameraFrustum c = handCamera();
  const std::vector<Aabb> recv = {box({-0.5f, -0.5f, -2.5f}, {0.5f, 0.5f, -1.5f})};
  const std::vector<Aabb> casters = {box({-0.2f, -0.2f, 1.0f}, {0.2f, 0.2f, 2.0f})};  // behind the eye
  CHECK(virtualCameraShift(c, casters) == doctest::Approx(3.0));                      // z_max 2 + zNear 1
  std::vector<glm::dvec3> a, b, d;
  OriginalPsm o = fitOriginalPsm(c, {0.3, 1, 1, 0}, recv, casters, {}, a, b, d);
  CHECK(o.shift == doctest::Approx(3.0));
  CHECK(o.virtualCamera.zNear == doctest::Approx(4.0));
  REQUIRE(o.fit.status == FitStatus::Ok);
  CHECK(o.fit.camera.kind == LightProjection::ReversedPerspective);
  o = fitOriginalPsm(c, {0.3, 1, -1, 0}, recv, casters, {}, a, b, d);
  CHECK(o.shift == 0.0);
  CHECK(o.fit.camera.kind == LightProjection::Perspective);
}

TEST_CASE("psm camera: a light inside the receivers' hull reports ConeTooWide, none visible NoReceivers") {
  const CameraFrustum c = handCamera();
  const std::vector<Aabb> recv = {box({-0.9f, -0.9f, -2.9f}, {-0.1f, 0.9f, -1.1f}),
                                  box({0.1f, -0.9f, -2.9f}, {0.9f, 0.9f, -1.1f})};
  PsmFitter fitter;
  CHECK(fitter.fit(c, {0, 0, -2, 1}, recv).status == FitStatus::ConeTooWide);
  const std::vector<Aabb> none = {box({10, 10, 10}, {11, 11, 11})};
  CHECK(fitter.fit(c, {0, 5, -2, 1}, none).status == FitStatus::NoReceivers);
}

// Grader for lesson 09 (make grade LESSON=09): the public cases. Hand-computed cases, then seeded random
// ones that check the statement's formulas and properties. More cases, with seeds the grader
// chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab::ex09;
using shadowlab::grading::kApprox;
using shadowlab::grading::relativeTolerance;

namespace {
double depthAt(const glm::dmat4& m, double Z) {  // a point on the axis at distance Z (view z = -Z)
  const glm::dvec4 h = m * glm::dvec4(0.0, 0.0, -Z, 1.0);
  return h.z / h.w;
}
// Brute force for the cone: every candidate through 1, 2 or 3 directions.
double bruteHalfAngle(const std::vector<glm::dvec3>& d) {
  std::vector<glm::dvec3> u;
  for (auto v : d) u.push_back(glm::normalize(v));
  double best = 1e9;
  auto test = [&](glm::dvec3 axis) {
    if (glm::length(axis) < 1e-12) return;
    for (double s : {1.0, -1.0}) {
      const glm::dvec3 a = s * glm::normalize(axis);
      double worst = 0;
      for (auto& v : u) worst = std::max(worst, std::atan2(glm::length(glm::cross(a, v)), glm::dot(a, v)));
      best = std::min(best, worst);
    }
  };
  for (std::size_t i = 0; i < u.size(); ++i) {
    test(u[i]);
    for (std::size_t j = i + 1; j < u.size(); ++j) {
      test(u[i] + u[j]);
      for (std::size_t k = j + 1; k < u.size(); ++k) test(glm::cross(u[j] - u[i], u[k] - u[i]));
    }
  }
  return best;
}
}  // namespace

TEST_CASE("ex09.1: the inverse projection matrix, entry by entry") {
  // fovY 90 degrees -> cot(45) = 1; aspect 2 -> x scale 1/2; a = 0.5: z row gives a * w, w = -z.
  const glm::dmat4 m = inverseProjection(std::numbers::pi / 2.0, 2.0, 0.5);
  glm::dmat4 want(0.0);
  want[0][0] = 0.5;
  want[1][1] = 1.0;
  want[3][2] = 0.5;
  want[2][3] = -1.0;
  CHECK_NEAR(m, want, 1e-9);
}

TEST_CASE("ex09.1: depth -1 at Z = -a, +1 at Z = +a, 0 at infinity, order kept through infinity") {
  const double a = 0.25;
  const glm::dmat4 m = inverseProjection(1.0, 1.0, a);
  CAPTURE(m);
  CHECK_NEAR(depthAt(m, -a), -1.0, kApprox);
  CHECK_NEAR(depthAt(m, a), 1.0, kApprox);
  CHECK_NEAR(depthAt(m, 1e12), 0.0, 1e-9);
  CHECK_NEAR(depthAt(m, -1e12), 0.0, 1e-9);
  // The ray of [Kozlov04] §3: Z = -a ... -inf, then +inf ... +a: depth rises all the way.
  const double Zs[] = {-0.25, -0.5, -2.0, -100.0, 100.0, 2.0, 0.5, 0.25};
  for (int i = 1; i < 8; ++i) {
    INFO("depth at Z = ", Zs[i - 1], " is ", depthAt(m, Zs[i - 1]), "; at Z = ", Zs[i], " it is ", depthAt(m, Zs[i]));
    CHECK_TRUE(depthAt(m, Zs[i]) > depthAt(m, Zs[i - 1]));
  }
}

TEST_CASE("ex09.1: random a and Z match the paper's Z_psm = (1 + a/Z) / 2") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex09.1 random"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double a = 1e-3 + u(rng), fov = 0.2 + 2.5 * u(rng), aspect = 0.5 + u(rng);
    double Z = (u(rng) < 0.5 ? -1.0 : 1.0) * a * (1.0 + 100.0 * u(rng));
    const glm::dmat4 m = inverseProjection(fov, aspect, a);
    INFO("random case ", i, " of 200 (seed ", shadowlab::test::seed(), "): a ", a, ", fovY ", fov, ", aspect ", aspect,
         ", Z ", Z);
    if (!CHECK_NEAR((depthAt(m, Z) + 1.0) / 2.0, 0.5 * (1.0 + a / Z), kApprox)) break;
    // x and y as an ordinary perspective: x = Z tan(fov/2) aspect lands on the right edge.
    const double x = std::abs(Z) * std::tan(fov / 2.0) * aspect;
    const glm::dvec4 h = m * glm::dvec4(x, 0.0, -std::abs(Z), 1.0);
    if (!CHECK_NEAR(h.x / h.w, 1.0, kApprox)) break;
  }
}

TEST_CASE("ex09.2: the smallest enclosing cone of hand-made direction sets") {
  INFO("directions (1, 0, 0), (0, 2, 0)");
  CHECK_NEAR(smallestEnclosingCone({{1, 0, 0}, {0, 2, 0}}),
             glm::dvec4(std::sqrt(0.5), std::sqrt(0.5), 0.0, std::numbers::pi / 4.0), 1e-5);
  const double s = 1.0 / std::sqrt(3.0);
  INFO("directions (1, 0, 0), (0, 1, 0), (0, 0, 5)");
  CHECK_NEAR(smallestEnclosingCone({{1, 0, 0}, {0, 1, 0}, {0, 0, 5}}), glm::dvec4(s, s, s, std::acos(s)), 1e-5);
  // A direction inside the cone of the other two changes nothing.
  INFO("directions (1, 0, 0), (0, 1, 0), (1, 1, 0.1)");
  CHECK_NEAR(smallestEnclosingCone({{1, 0, 0}, {0, 1, 0}, {1, 1, 0.1}}).w, std::numbers::pi / 4.0, 1e-5);
}

TEST_CASE("ex09.2: random sets: holds every direction with the brute-force optimal angle") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex09.2 random"));
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.05, 1.2);
  for (int i = 0; i < 100; ++i) {
    const glm::dvec3 centre = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const double spread = u(rng);
    std::vector<glm::dvec3> d;
    const int n = 2 + static_cast<int>(rng() % 9);
    for (int k = 0; k < n; ++k)
      d.push_back((centre + spread * glm::dvec3(g(rng), g(rng), g(rng)) * 0.5) * (0.5 + u(rng)));
    bool hemisphere = true;
    for (auto& v : d) hemisphere = hemisphere && glm::dot(v, centre) > 0.05 * glm::length(v);
    if (!hemisphere) continue;
    const glm::dvec4 c = smallestEnclosingCone(d);
    const glm::dvec3 axis(c);
    INFO("random case ", i, " of 100 (seed ", shadowlab::test::seed(), "): ", n, " directions, the first ",
         shadowlab::grading::show(d[0]));
    CAPTURE(c);
    if (!CHECK_NEAR(glm::length(axis), 1.0, kApprox)) break;
    double widest = 0;
    for (auto& v : d) widest = std::max(widest, std::atan2(glm::length(glm::cross(axis, v)), glm::dot(axis, v)));
    INFO("the widest angle between the axis and a direction: ", widest);
    if (!CHECK_TRUE(widest <= c.w + 1e-9)) break;
    if (!CHECK_NEAR(c.w, bruteHalfAngle(d), relativeTolerance(1e-6))) break;
  }
}

TEST_CASE("ex09.3: the visible faces of the unit cube from hand-placed lights") {
  // In front at (0,0,5): only the +z face is seen; the other five carry maps.
  // Faces 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
  auto faces = [](const glm::dvec4& light) {
    int seen = 0;  // bit f: face f is visible
    for (int f = 0; f < 6; ++f) seen |= cubeFaceVisible(f, light) ? 1 << f : 0;
    return seen;
  };
  INFO("the result as a bit set: bit f = face f visible (1 +x, 2 -x, 4 +y, 8 -y, 16 +z, 32 -z)");
  // In front at (0,0,5): only the +z face is seen; the other five carry maps.
  CHECK_EXACT(faces({0, 0, 5, 1}), 1 << 4);
  // Behind the camera at (2,2,-3) (w = -1): +x, +y and -z seen; the test is geometric.
  CHECK_EXACT(faces({2, 2, -3, -1}), 1 << 0 | 1 << 2 | 1 << 5);
  // Inside the cube: sees no face from outside; all 6 carry maps.
  CHECK_EXACT(faces({0.2, -0.5, 0.9, 1}), 0);
  // Direction toward +x: +x seen, -x used, the four others edge-on (seen, unused).
  CHECK_EXACT(faces({1, 0, 0, 0}), 63 & ~(1 << 1));
  // Direction toward (-1, 1, 1): -x, +y, +z seen.
  CHECK_EXACT(faces({-1, 1, 1, 0}), 1 << 1 | 1 << 2 | 1 << 4);
  // Exactly on the plane of +y (edge-on): counts as visible.
  CHECK_EXACT(cubeFaceVisible(2, {3, 1, 0, 1}), true);
}

TEST_CASE("ex09.3: random outside lights leave 3 to 5 faces, inside ones 6") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex09.3 random"));
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 p(u(rng), u(rng), u(rng));
    int hidden = 0;
    for (int f = 0; f < 6; ++f) hidden += cubeFaceVisible(f, glm::dvec4(p, 1.0)) ? 0 : 1;
    const bool inside = glm::all(glm::lessThan(glm::abs(p), glm::dvec3(1.0)));
    INFO("random case ", i, " of 300 (seed ", shadowlab::test::seed(), "): a light at ", shadowlab::grading::show(p),
         std::string(inside ? " (inside the cube)" : " (outside the cube)"), ", ", hidden, " faces not seen");
    if (!CHECK_TRUE(inside ? hidden == 6 : hidden >= 3 && hidden <= 5)) break;
    // Brute force: a face is visible iff the light is on the outer side of its plane.
    bool ok = true;
    for (int f = 0; f < 6 && ok; ++f) {
      const double coord = (f % 2 == 0 ? 1.0 : -1.0) * p[f / 2];
      INFO("face ", f);
      ok = CHECK_EXACT(cubeFaceVisible(f, glm::dvec4(p, 1.0)), coord >= 1.0);
    }
    if (!ok) break;
  }
}

TEST_CASE("ex09.4: the texel-size bias with an affine map, by hand") {
  // M scales by 1/2: NDC x spans world [-2, 2]; with 4 texels one texel is 1 world unit, in x and
  // in y, so L_texel = sqrt(2). a = 0.1, b = 2, light straight down -z.
  glm::dmat4 M(0.5);
  M[3][3] = 1.0;
  CAPTURE(M);
  CHECK_NEAR(texelSizeBias(M, {1, 2, 3}, {0, 0, -2}, 0.1, 2.0, 4.0),
             glm::dvec3(1, 2, 3.0 - (0.1 + 2.0 * std::sqrt(2.0))), kApprox);
  // b = 0: only the constant part moves the point, along the light.
  CHECK_NEAR(texelSizeBias(M, {0, 0, 0}, {1, 0, 0}, 0.25, 0.0, 1024.0), glm::dvec3(0.25, 0, 0), kApprox);
}

TEST_CASE("ex09.4: random perspective maps: moves away from the light by a + b L_texel") {
  std::mt19937_64 rng(shadowlab::test::seedFor("ex09.4 random"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    // A light camera at the origin looking down -z: GL perspective, fov 60 degrees, n 1, f 100.
    const double n = 1.0, f = 100.0, t = 1.0 / std::tan(std::numbers::pi / 6.0);
    glm::dmat4 M(0.0);
    M[0][0] = t;
    M[1][1] = t;
    M[2][2] = -(f + n) / (f - n);
    M[3][2] = -2.0 * f * n / (f - n);
    M[2][3] = -1.0;
    const double depth = 2.0 + 90.0 * u(rng);
    const glm::dvec3 p((u(rng) - 0.5) * depth, (u(rng) - 0.5) * depth, -depth);
    const glm::dvec3 L = glm::normalize(p);
    const double S = 256.0 + 1024.0 * u(rng), a = 0.01 * u(rng), b = 0.5 + u(rng);
    // One texel step at constant depth: the perspective scales it by depth / t on each axis.
    const double texel = std::sqrt(2.0) * (2.0 / S) * depth / t;
    const glm::dvec3 r = texelSizeBias(M, p, L * 3.0, a, b, S);
    INFO("random case ", i, " of 200 (seed ", shadowlab::test::seed(), "): a ", a, ", b ", b, ", map ", S);
    CAPTURE(p);
    CAPTURE(r);
    if (!CHECK_NEAR(glm::length(r - p), a + b * texel, relativeTolerance(1e-6))) break;
    if (!CHECK_NEAR(glm::dot(r - p, L), glm::length(r - p), kApprox)) break;  // along L, away from the light
  }
}

TEST_CASE("ex09.5: LiSPSM's n_opt by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // z0 = 1, z1 = 100: z0 + sqrt(z0 z1) = 11; gamma = 90 degrees: sin = 1.
  CHECK_NEAR(lispsmOptimalN(1.0, 100.0, std::numbers::pi / 2.0), 11.0, kApprox);
  // gamma = 30 degrees: sin = 1/2, n doubles.
  CHECK_NEAR(lispsmOptimalN(1.0, 100.0, std::numbers::pi / 6.0), 22.0, kApprox);
  // z0 = 4, z1 = 9: 4 + 6 = 10; gamma = 150 degrees: sin = 1/2 as well.
  CHECK_NEAR(lispsmOptimalN(4.0, 9.0, 5.0 * std::numbers::pi / 6.0), 20.0, kApprox);
  // Light along the view (gamma = 0): no warp helps.
  CHECK_NEAR(lispsmOptimalN(1.0, 100.0, 0.0), std::numeric_limits<double>::infinity(), 0.0);
}

TEST_CASE("ex09.5: random ranges: n_opt equalises the aliasing at both ends") {
  // LiSPSM's aliasing along depth for an overhead light (Wimmer et al.): with z' = z - z0 + n,
  // m(z) is proportional to z'^2 / z; n_opt (gamma = 90 degrees) makes m(z0) = m(z1).
  std::mt19937_64 rng(shadowlab::test::seedFor("ex09.5 random"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double z0 = 0.01 + 10.0 * u(rng), z1 = z0 * (1.5 + 1000.0 * u(rng)), gamma = 0.05 + 3.0 * u(rng);
    const double n = lispsmOptimalN(z0, z1, std::numbers::pi / 2.0);
    const double m0 = n * n / z0, m1 = (z1 - z0 + n) * (z1 - z0 + n) / z1;
    INFO("random case ", i, " of 200 (seed ", shadowlab::test::seed(), "): z0 ", z0, ", z1 ", z1, ", n_opt ", n);
    INFO("m(z0) = n^2 / z0 against m(z1) = (z1 - z0 + n)^2 / z1");
    if (!CHECK_NEAR(m0, m1, relativeTolerance(1e-9))) break;
    INFO("at gamma ", gamma, ": n_opt(gamma) |sin gamma| = n_opt(90 degrees)");
    if (!CHECK_NEAR(lispsmOptimalN(z0, z1, gamma) * std::abs(std::sin(gamma)), n, relativeTolerance(1e-12))) break;
  }
}

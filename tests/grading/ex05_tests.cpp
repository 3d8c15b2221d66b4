// Graders for lesson 05 (make grade LESSON=05): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases compare with the reference implementation (compiled into
// the course library) and check properties any correct answer has. More cases, with seeds the
// grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <random>
#include <utility>

#include "algorithms/moment_maps.hpp"
#include "algorithms/soft_shadows.hpp"
#include "ex05_grids.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::kApprox;
using grading::relativeTolerance;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("ex05.1: the penumbra half-width by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  CHECK_NEAR(ex05::penumbraHalfWidth(2.0f, 1.0f, 0.5f, 8.0f), 0.125f, kApprox);  // 2 * 0.5 / 8
  CHECK_NEAR(ex05::penumbraHalfWidth(2.0f, 0.5f, 0.5f, 8.0f), 0.25f, kApprox);   // n.L = 1/2 doubles it
  CHECK_NEAR(ex05::penumbraHalfWidth(0.0f, 1.0f, 0.5f, 8.0f), 0.0f, kApprox);    // contact: hard
  CHECK_NEAR(ex05::penumbraHalfWidth(2.0f, 1.0f, 0.0f, 8.0f), 0.0f, kApprox);    // a point light
  // The lesson's test edge: d = 2.31, n.L = 0.868, R = 0.5, D = 8.06 -> 2.31 / 0.868 * 0.0620 = 0.1651.
  CHECK_NEAR(ex05::penumbraHalfWidth(2.31f, 0.868f, 0.5f, 8.06f), 0.16510f, relativeTolerance(2e-4));
}

TEST_CASE("ex05.1: random geometry against the reference") {
  std::mt19937_64 rng(test::seedFor("ex05.1"));
  std::uniform_real_distribution<float> u(0.1f, 10.0f), c(0.05f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const float d = u(rng), nDotL = c(rng), R = 0.1f * u(rng), D = u(rng) + 1.0f;
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): d ", d, ", n.L ", nDotL, ", R ", R, ", D ", D);
    if (!CHECK_NEAR(ex05::penumbraHalfWidth(d, nDotL, R, D), soft::penumbraHalfWidth(d, nDotL, R, D), kApprox)) break;
  }
}

TEST_CASE("ex05.2: A_frac and its linear approximation by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  CHECK_NEAR(ex05::visibleFraction(-1.0f), 0.0f, kApprox);
  CHECK_NEAR(ex05::visibleFraction(0.0f), 0.5f, kApprox);
  CHECK_NEAR(ex05::visibleFraction(1.0f), 1.0f, kApprox);
  // t = 1/2: 1/2 + (0.5 * 0.8660254 + pi/6) / pi = 1/2 + (0.4330127 + 0.5235988) / pi = 0.8044989.
  CHECK_NEAR(ex05::visibleFraction(0.5f), 0.8044989f, kApprox);
  CHECK_NEAR(ex05::visibleFraction(-0.5f), 0.1955011f, kApprox);
  CHECK_NEAR(ex05::visibleFraction(3.0f), 1.0f, kApprox);   // clamped
  CHECK_NEAR(ex05::visibleFraction(-3.0f), 0.0f, kApprox);  // clamped
  CHECK_NEAR(ex05::visibleFractionLinear(0.5f), 0.75f, kApprox);
  CHECK_NEAR(ex05::visibleFractionLinear(-1.0f), 0.0f, kApprox);
  CHECK_NEAR(ex05::visibleFractionLinear(2.0f), 1.0f, kApprox);
  // Where they differ most: t* = sqrt(1 - pi^2 / 16) = 0.618991, by 0.0577105.
  const float t = 0.618991f;
  CHECK_NEAR(ex05::visibleFraction(t) - ex05::visibleFractionLinear(t), 0.0577105f, 1e-5);
}

TEST_CASE("ex05.2: random t against the reference, symmetric") {
  std::mt19937_64 rng(test::seedFor("ex05.2"));
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  for (int i = 0; i < 200; ++i) {
    const float t = u(rng);
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): t ", t);
    if (!CHECK_NEAR(ex05::visibleFraction(t), soft::visibleFraction(t), kApprox)) break;
    if (!CHECK_NEAR(ex05::visibleFractionLinear(t), soft::visibleFractionLinear(t), kApprox)) break;
    INFO("the part of the disk left of -t is what is right of t");
    if (!CHECK_NEAR(ex05::visibleFraction(t) + ex05::visibleFraction(-t), 1.0f, kApprox)) break;
  }
}

TEST_CASE("ex05.3: the PCSS filter radius by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // Receiver 10 along the axis, blocker at 8, R = 0.5: w = 2 / 8 * 0.5 = 0.125; one uv unit at the
  // receiver is 2 * 10 * 0.5 = 10 m (tan(fov/2) = 0.5), so 0.0125.
  CHECK_NEAR(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 8.0f, 0.5f), 0.0125f, kApprox);
  // Halfway to the light: w = 5 / 5 * 0.5 = 0.5, uv 0.05.
  CHECK_NEAR(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 5.0f, 0.5f), 0.05f, kApprox);
  // A contact (blocker at the receiver) and a "blocker" behind it: no penumbra.
  CHECK_NEAR(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 10.0f, 0.5f), 0.0f, kApprox);
  CHECK_NEAR(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 12.0f, 0.5f), 0.0f, kApprox);
  // A wider frustum spreads one uv over more world: tan(fov/2) = 1 halves it.
  CHECK_NEAR(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 8.0f, 1.0f), 0.00625f, kApprox);
}

TEST_CASE("ex05.3: random depths against the reference") {
  std::mt19937_64 rng(test::seedFor("ex05.3"));
  std::uniform_real_distribution<float> u(0.5f, 50.0f), r(0.05f, 2.0f), t(0.2f, 2.0f);
  for (int i = 0; i < 200; ++i) {
    const float zr = u(rng), zb = u(rng), R = r(rng), tanHalf = t(rng);
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): R ", R, ", zReceiver ", zr, ", zBlocker ", zb,
         ", tanHalfFov ", tanHalf);
    if (!CHECK_NEAR(ex05::pcssFilterRadiusUv(R, zr, zb, tanHalf), soft::pcssFilterRadiusUv(R, zr, zb, tanHalf),
                    kApprox))
      break;
  }
}

TEST_CASE("ex05.4: Poisson tap rotation by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // A quarter turn: x to y.
  CHECK_NEAR(ex05::rotateTap({1.0f, 0.0f}, float(kPi / 2)), glm::vec2(0.0f, 1.0f), 1e-6);
  // Half a turn: the point reflected.
  CHECK_NEAR(ex05::rotateTap({0.3f, 0.4f}, float(kPi)), glm::vec2(-0.3f, -0.4f), 1e-6);
  // 30 degrees: (0, 1) -> (-sin 30, cos 30) = (-0.5, 0.8660254).
  CHECK_NEAR(ex05::rotateTap({0.0f, 1.0f}, float(kPi / 6)), glm::vec2(-0.5f, 0.8660254f), 1e-6);
}

TEST_CASE("ex05.4: random taps against the reference, keeping their length") {
  std::mt19937_64 rng(test::seedFor("ex05.4"));
  std::uniform_real_distribution<float> u(-1, 1), a(-6.2f, 6.2f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec2 p(u(rng), u(rng));
    const float angle = a(rng);
    const glm::vec2 q = ex05::rotateTap(p, angle);
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): angle ", angle);
    CAPTURE(p);
    if (!CHECK_NEAR(q, soft::rotateTap(p, angle), 1e-5)) break;
    if (!CHECK_NEAR(glm::length(q), glm::length(p), 1e-5)) break;
  }
}

TEST_CASE("ex05.5: the light mesh's trilinear average by hand") {
  // One lit node (1, 1, 1) = 1, the rest 0. At (1.25, 1.5, 1): fractions (0.25, 0.5, 0) in the
  // cell from (1, 1, 1): its weight (1 - 0.25)(1 - 0.5)(1 - 0) = 0.375.
  const auto single =
      test::lightGrid([](float x, float y, float z) { return x == 1 && y == 1 && z == 1 ? 1.0f : 0.0f; });
  INFO("a 5 x 3 x 4 grid of nodes 1 m apart from the origin, 1 at node (1, 1, 1), 0 elsewhere");
  CHECK_NEAR(ex05::lightMeshVisibility(single, {1.25f, 1.5f, 1.0f}), 0.375f, kApprox);
  CHECK_NEAR(ex05::lightMeshVisibility(single, {1.0f, 1.0f, 1.0f}), 1.0f, kApprox);    // on the node
  CHECK_NEAR(ex05::lightMeshVisibility(single, {0.5f, 0.5f, 0.5f}), 0.125f, kApprox);  // cell centre
  CHECK_NEAR(ex05::lightMeshVisibility(single, {3.0f, 2.0f, 3.0f}), 0.0f, kApprox);
}

TEST_CASE("ex05.5: outside the grid, clamped to the nearest face") {
  // Never a read past the end: the ramp x / 4 is 0 left of the grid and 1 right of it.
  const auto ramp = test::lightGrid([](float x, float, float) { return x / 4.0f; });
  INFO("a 5 x 3 x 4 grid of nodes 1 m apart from the origin, holding x / 4");
  CHECK_NEAR(ex05::lightMeshVisibility(ramp, {-2.0f, 1.0f, 1.0f}), 0.0f, kApprox);
  CHECK_NEAR(ex05::lightMeshVisibility(ramp, {9.0f, 1.0f, 1.0f}), 1.0f, kApprox);
  CHECK_NEAR(ex05::lightMeshVisibility(ramp, {4.0f, 2.0f, 3.0f}), 1.0f, kApprox);  // the last node
}

TEST_CASE("ex05.5: random points and grids against the reference") {
  std::mt19937_64 rng(test::seedFor("ex05.5"));
  std::uniform_real_distribution<float> u(0, 1);
  auto g = test::lightGrid([](float, float, float) { return 0.0f; });
  for (float& v : g.visibility) v = u(rng);
  g.origin = {-3, 1, 2};
  g.step = {2.0f, 0.5f, 1.5f};
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 p = g.origin + glm::vec3(11 * u(rng) - 1, 2 * u(rng) - 0.5f, 7 * u(rng) - 1);
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): a 5 x 3 x 4 grid of random values from (-3, 1, 2), ",
         "steps (2, 0.5, 1.5)");
    CAPTURE(p);
    if (!CHECK_NEAR(ex05::lightMeshVisibility(g, p), soft::lightMeshVisibility(g, p), 1e-5)) break;
  }
}

namespace {
// The mean of (z, z^2, z^3, z^4) over depths z with weights w (summing to 1).
glm::dvec4 momentsOf(std::initializer_list<std::pair<double, double>> atoms) {
  glm::dvec4 b(0.0);
  for (const auto& [z, w] : atoms) b += w * glm::dvec4(z, z * z, z * z * z, z * z * z * z);
  return b;
}
}  // namespace

TEST_CASE("ex05.7: the Hamburger bound by hand: three deltas, t on one of them" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // Weights 1/4, 1/2, 1/4 at depths 0.2, 0.5, 0.8: with t on a delta, the three-delta solution is
  // the distribution itself, so the lit share is the weight not in front of t.
  const glm::dvec4 b = momentsOf({{0.2, 0.25}, {0.5, 0.5}, {0.8, 0.25}});
  INFO("moments of 1/4 at 0.2, 1/2 at 0.5, 1/4 at 0.8, alpha 0");
  CHECK_NEAR(ex05::msmLitShare(b, 0.2, 0.0), 1.0, 1e-6);   // nothing in front
  CHECK_NEAR(ex05::msmLitShare(b, 0.5, 0.0), 0.75, 1e-6);  // 1/4 in front
  CHECK_NEAR(ex05::msmLitShare(b, 0.8, 0.0), 0.25, 1e-6);  // 3/4 in front
  CHECK_NEAR(ex05::msmLitShare(b, 0.1, 0.0), 1.0, 1e-6);   // in front of everything: lit
}

TEST_CASE("ex05.7: random depth mixtures against the reference, and never darker than the truth") {
  std::mt19937_64 rng(test::seedFor("ex05.7"));
  std::uniform_real_distribution<double> depth(0.05, 0.95), weight(0.1, 1.0), alpha(0.0, 1e-4);
  for (int i = 0; i < 200; ++i) {
    double z[4], w[4], sum = 0;
    for (int k = 0; k < 4; ++k) z[k] = depth(rng), w[k] = weight(rng), sum += w[k];
    glm::dvec4 b(0.0);
    for (int k = 0; k < 4; ++k) b += w[k] / sum * soft::msmMoments(z[k]);
    const double t = depth(rng), a = alpha(rng);
    double truth = 0;  // the share of the mixture not in front of t
    for (int k = 0; k < 4; ++k) truth += z[k] >= t ? w[k] / sum : 0.0;
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): depths ", z[0], ", ", z[1], ", ", z[2], ", ", z[3],
         ", weights ", w[0] / sum, ", ", w[1] / sum, ", ", w[2] / sum, ", ", w[3] / sum, ", t ", t, ", alpha ", a);
    const double lit = ex05::msmLitShare(b, t, a);
    if (!CHECK_NEAR(lit, soft::msmLitShare(b, t, a), 1e-6)) break;
    if (lit < truth - 1e-3) {  // a bound: light may bleed, shadow is never invented
      CHECK(lit >= truth - 1e-3);
      break;
    }
  }
}

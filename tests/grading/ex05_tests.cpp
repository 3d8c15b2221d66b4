// Graders for lesson 05 (ctest -L ex05). Expected values are worked out by hand in the comments;
// the randomised cases compare against the rules written out independently here.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("ex05.1: the penumbra half-width by hand") {
  CHECK(ex05::penumbraHalfWidth(2.0f, 1.0f, 0.5f, 8.0f) == doctest::Approx(0.125f));  // 2 * 0.5 / 8
  CHECK(ex05::penumbraHalfWidth(2.0f, 0.5f, 0.5f, 8.0f) == doctest::Approx(0.25f));   // n.L = 1/2 doubles it
  CHECK(ex05::penumbraHalfWidth(0.0f, 1.0f, 0.5f, 8.0f) == doctest::Approx(0.0f));    // contact: hard
  CHECK(ex05::penumbraHalfWidth(2.0f, 1.0f, 0.0f, 8.0f) == doctest::Approx(0.0f));    // a point light
  // The lesson's test edge: d = 2.31, n.L = 0.868, R = 0.5, D = 8.06 -> 2.31 / 0.868 * 0.0620 = 0.1651.
  CHECK(ex05::penumbraHalfWidth(2.31f, 0.868f, 0.5f, 8.06f) == doctest::Approx(0.16510).epsilon(1e-3));
}

TEST_CASE("ex05.1: random geometry: linear in d and R, inverse in n.L and D") {
  std::mt19937_64 rng(test::seedFor("ex05.1"));
  std::uniform_real_distribution<float> u(0.1f, 10.0f), c(0.05f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const float d = u(rng), nDotL = c(rng), R = 0.1f * u(rng), D = u(rng) + 1.0f;
    INFO("seed ", test::seed(), " case ", i);
    CHECK(ex05::penumbraHalfWidth(d, nDotL, R, D) ==
          doctest::Approx(double(d) * R / (double(nDotL) * D)).epsilon(1e-5));
  }
}

TEST_CASE("ex05.2: A_frac and its linear approximation by hand") {
  CHECK(ex05::visibleFraction(-1.0f) == doctest::Approx(0.0f));
  CHECK(ex05::visibleFraction(0.0f) == doctest::Approx(0.5f));
  CHECK(ex05::visibleFraction(1.0f) == doctest::Approx(1.0f));
  // t = 1/2: 1/2 + (0.5 * 0.8660254 + pi/6) / pi = 1/2 + (0.4330127 + 0.5235988) / pi = 0.8044989.
  CHECK(ex05::visibleFraction(0.5f) == doctest::Approx(0.8044989));
  CHECK(ex05::visibleFraction(-0.5f) == doctest::Approx(0.1955011));
  CHECK(ex05::visibleFraction(3.0f) == doctest::Approx(1.0f));   // clamped
  CHECK(ex05::visibleFraction(-3.0f) == doctest::Approx(0.0f));  // clamped
  CHECK(ex05::visibleFractionLinear(0.5f) == doctest::Approx(0.75f));
  CHECK(ex05::visibleFractionLinear(-1.0f) == doctest::Approx(0.0f));
  CHECK(ex05::visibleFractionLinear(2.0f) == doctest::Approx(1.0f));
  // Where they differ most: t* = sqrt(1 - pi^2 / 16) = 0.618991, by 0.0577105.
  const float t = 0.618991f;
  CHECK(ex05::visibleFraction(t) - ex05::visibleFractionLinear(t) == doctest::Approx(0.0577105).epsilon(1e-4));
}

TEST_CASE("ex05.2: random t: the disk's area fraction, symmetric, monotone") {
  std::mt19937_64 rng(test::seedFor("ex05.2"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double t = u(rng);
    // The area of the unit disk left of x = t, by the midpoint rule over 2000 strips, over pi.
    double area = 0;
    for (int k = 0; k < 2000; ++k) {
      const double x = -1.0 + (t + 1.0) * (k + 0.5) / 2000.0;
      area += 2.0 * std::sqrt(std::max(0.0, 1.0 - x * x)) * (t + 1.0) / 2000.0;
    }
    INFO("seed ", test::seed(), " t ", t);
    CHECK(ex05::visibleFraction(float(t)) == doctest::Approx(area / kPi).epsilon(1e-3));
    CHECK(ex05::visibleFraction(float(t)) + ex05::visibleFraction(float(-t)) == doctest::Approx(1.0));
    CHECK(ex05::visibleFractionLinear(float(t)) == doctest::Approx(0.5 * (1.0 + t)));
  }
}

TEST_CASE("ex05.3: the PCSS filter radius by hand") {
  // Receiver 10 along the axis, blocker at 8, R = 0.5: w = 2 / 8 * 0.5 = 0.125; one uv unit at the
  // receiver is 2 * 10 * 0.5 = 10 m (tan(fov/2) = 0.5), so 0.0125.
  CHECK(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 8.0f, 0.5f) == doctest::Approx(0.0125f));
  // Halfway to the light: w = 5 / 5 * 0.5 = 0.5, uv 0.05.
  CHECK(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 5.0f, 0.5f) == doctest::Approx(0.05f));
  // A contact (blocker at the receiver) and a "blocker" behind it: no penumbra.
  CHECK(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 10.0f, 0.5f) == doctest::Approx(0.0f));
  CHECK(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 12.0f, 0.5f) == doctest::Approx(0.0f));
  // A wider frustum spreads one uv over more world: tan(fov/2) = 1 halves it.
  CHECK(ex05::pcssFilterRadiusUv(0.5f, 10.0f, 8.0f, 1.0f) == doctest::Approx(0.00625f));
}

TEST_CASE("ex05.3: random depths against the rule") {
  std::mt19937_64 rng(test::seedFor("ex05.3"));
  std::uniform_real_distribution<double> u(0.5, 50.0), r(0.05, 2.0), t(0.2, 2.0);
  for (int i = 0; i < 200; ++i) {
    const double zr = u(rng), zb = u(rng), R = r(rng), tanHalf = t(rng);
    const double expected = zb < zr ? (zr - zb) / zb * R / (2.0 * zr * tanHalf) : 0.0;
    INFO("seed ", test::seed(), " zr ", zr, " zb ", zb);
    CHECK(ex05::pcssFilterRadiusUv(float(R), float(zr), float(zb), float(tanHalf)) ==
          doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("ex05.4: Poisson tap rotation by hand") {
  const glm::vec2 q = ex05::rotateTap({1.0f, 0.0f}, float(kPi / 2));  // a quarter turn: x to y
  CHECK(q.x == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(q.y == doctest::Approx(1.0f));
  const glm::vec2 h = ex05::rotateTap({0.3f, 0.4f}, float(kPi));  // half a turn: the point reflected
  CHECK(h.x == doctest::Approx(-0.3f));
  CHECK(h.y == doctest::Approx(-0.4f));
  // 30 degrees: (0, 1) -> (-sin 30, cos 30) = (-0.5, 0.8660254).
  const glm::vec2 s = ex05::rotateTap({0.0f, 1.0f}, float(kPi / 6));
  CHECK(s.x == doctest::Approx(-0.5f));
  CHECK(s.y == doctest::Approx(0.8660254f));
}

TEST_CASE("ex05.4: random taps keep their length and turn by the angle") {
  std::mt19937_64 rng(test::seedFor("ex05.4"));
  std::uniform_real_distribution<float> u(-1, 1), a(-6.2f, 6.2f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec2 p(u(rng), u(rng));
    const float angle = a(rng);
    const glm::vec2 q = ex05::rotateTap(p, angle);
    INFO("seed ", test::seed(), " case ", i);
    CHECK(glm::length(q) == doctest::Approx(glm::length(p)).epsilon(1e-4));
    CHECK(glm::dot(p, q) == doctest::Approx(glm::dot(p, p) * std::cos(angle)).epsilon(1e-3));
    CHECK(p.x * q.y - p.y * q.x == doctest::Approx(glm::dot(p, p) * std::sin(angle)).epsilon(1e-3));
  }
}

namespace {
// A 5 x 3 x 4 grid, 1 m apart from the origin, with the visibility f at its nodes.
template <class F>
soft::LightGrid grid(F f) {
  soft::LightGrid g;
  g.origin = {0, 0, 0};
  g.step = glm::vec3(1.0f);
  g.nodes = {5, 3, 4};
  g.visibility.resize(g.count());
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) g.visibility[g.index({x, y, z})] = f(float(x), float(y), float(z));
  return g;
}
}  // namespace

TEST_CASE("ex05.5: the light mesh's trilinear average by hand") {
  // One lit node (1, 1, 1) = 1, the rest 0. At (1.25, 1.5, 1): fractions (0.25, 0.5, 0) in the
  // cell from (1, 1, 1): its weight (1 - 0.25)(1 - 0.5)(1 - 0) = 0.375.
  const auto single = grid([](float x, float y, float z) { return x == 1 && y == 1 && z == 1 ? 1.0f : 0.0f; });
  CHECK(ex05::lightMeshVisibility(single, {1.25f, 1.5f, 1.0f}) == doctest::Approx(0.375f));
  CHECK(ex05::lightMeshVisibility(single, {1.0f, 1.0f, 1.0f}) == doctest::Approx(1.0f));    // on the node
  CHECK(ex05::lightMeshVisibility(single, {0.5f, 0.5f, 0.5f}) == doctest::Approx(0.125f));  // cell centre
  CHECK(ex05::lightMeshVisibility(single, {3.0f, 2.0f, 3.0f}) == doctest::Approx(0.0f));
  // Outside the grid: clamped to the nearest face, never a read past the end.
  const auto ramp = grid([](float x, float, float) { return x / 4.0f; });
  CHECK(ex05::lightMeshVisibility(ramp, {-2.0f, 1.0f, 1.0f}) == doctest::Approx(0.0f));
  CHECK(ex05::lightMeshVisibility(ramp, {9.0f, 1.0f, 1.0f}) == doctest::Approx(1.0f));
  CHECK(ex05::lightMeshVisibility(ramp, {4.0f, 2.0f, 3.0f}) == doctest::Approx(1.0f));  // the last node
}

TEST_CASE("ex05.5: random points: linear fields come back exactly, a moved grid too") {
  std::mt19937_64 rng(test::seedFor("ex05.5"));
  std::uniform_real_distribution<float> ux(0, 4), uy(0, 2), uz(0, 3);
  auto field = [](float x, float y, float z) { return 0.1f * x + 0.2f * y - 0.05f * z + 0.3f; };
  const auto g = grid(field);
  soft::LightGrid moved = g;  // the same values on nodes 2 m apart from (-3, 1, 2)
  moved.origin = {-3, 1, 2};
  moved.step = glm::vec3(2.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 p(ux(rng), uy(rng), uz(rng));
    INFO("seed ", test::seed(), " case ", i);
    CHECK(ex05::lightMeshVisibility(g, p) == doctest::Approx(field(p.x, p.y, p.z)).epsilon(1e-4));
    CHECK(ex05::lightMeshVisibility(moved, moved.origin + 2.0f * p) ==
          doctest::Approx(field(p.x, p.y, p.z)).epsilon(1e-4));
  }
}

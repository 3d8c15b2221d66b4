// Hidden cases for lesson 05 (instructor tree only): the rules written out independently of the
// reference, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../ex05_grids.hpp"
#include "algorithms/moment_maps.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::relativeTolerance;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_SUITE("hidden") {
  TEST_CASE("ex05.1: random geometry against d R / (n.L D), grazing light included") {
    std::mt19937_64 rng(test::seedFor("ex05.1 hidden"));
    std::uniform_real_distribution<double> length(0.01, 20.0), cosine(0.02, 1.0);
    for (int i = 0; i < 300; ++i) {
      const double d = length(rng), nDotL = cosine(rng), radius = 0.05 * length(rng), distance = 1.0 + length(rng);
      const double expected = d * radius / (nDotL * distance);
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): d ", d, ", n.L ", nDotL, ", R ", radius, ", D ",
           distance);
      if (!CHECK_NEAR(ex05::penumbraHalfWidth(float(d), float(nDotL), float(radius), float(distance)), expected,
                      relativeTolerance(1e-5)))
        break;
    }
  }

  TEST_CASE("ex05.2: random t: the disk's area fraction by the midpoint rule, the line (1 + t) / 2") {
    std::mt19937_64 rng(test::seedFor("ex05.2 hidden"));
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const double t = u(rng);
      // The area of the unit disk left of x = t, by the midpoint rule over 2000 strips, over pi.
      double area = 0;
      for (int k = 0; k < 2000; ++k) {
        const double x = -1.0 + (t + 1.0) * (k + 0.5) / 2000.0;
        area += 2.0 * std::sqrt(std::max(0.0, 1.0 - x * x)) * (t + 1.0) / 2000.0;
      }
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): t ", t);
      if (!CHECK_NEAR(ex05::visibleFraction(float(t)), area / kPi, 1e-4)) break;
      if (!CHECK_NEAR(ex05::visibleFractionLinear(float(t)), 0.5 * (1.0 + t), 1e-6)) break;
    }
  }

  TEST_CASE("ex05.3: random depths against (zr - zb) / zb R / (2 zr tan), 0 behind") {
    std::mt19937_64 rng(test::seedFor("ex05.3 hidden"));
    std::uniform_real_distribution<double> u(0.5, 50.0), r(0.05, 2.0), t(0.2, 2.0);
    for (int i = 0; i < 300; ++i) {
      const double zr = u(rng), zb = u(rng), R = r(rng), tanHalf = t(rng);
      const double expected = zb < zr ? (zr - zb) / zb * R / (2.0 * zr * tanHalf) : 0.0;
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): R ", R, ", zReceiver ", zr, ", zBlocker ", zb,
           ", tanHalfFov ", tanHalf);
      if (!CHECK_NEAR(ex05::pcssFilterRadiusUv(float(R), float(zr), float(zb), float(tanHalf)), expected,
                      relativeTolerance(1e-4)))
        break;
    }
  }

  TEST_CASE("ex05.4: random taps turn by the angle: cos and sin from the dot and cross products") {
    std::mt19937_64 rng(test::seedFor("ex05.4 hidden"));
    std::uniform_real_distribution<float> radius(0.05f, 1.0f), turn(-6.2f, 6.2f);
    for (int i = 0; i < 300; ++i) {  // taps on the unit disk, as the Poisson taps lie
      const float r = radius(rng), phase = turn(rng), angle = turn(rng);
      const glm::vec2 tap = r * glm::vec2(std::cos(phase), std::sin(phase)), q = ex05::rotateTap(tap, angle);
      INFO("random tap ", i, " of 300 (seed ", test::seed(), "): radius ", r, ", phase ", phase, ", turned by ", angle);
      CAPTURE(q);
      if (!CHECK_NEAR(glm::dot(tap, q), r * r * std::cos(angle), 1e-4)) break;
      if (!CHECK_NEAR(tap.x * q.y - tap.y * q.x, r * r * std::sin(angle), 1e-4)) break;
    }
  }

  TEST_CASE("ex05.5: random points: linear fields come back exactly, a moved grid too") {
    std::mt19937_64 rng(test::seedFor("ex05.5 hidden"));
    std::uniform_real_distribution<float> ux(0, 4), uy(0, 2), uz(0, 3);
    auto field = [](float x, float y, float z) { return 0.1f * x + 0.2f * y - 0.05f * z + 0.3f; };
    const soft::LightGrid g = test::lightGrid(field);  // 5 x 3 x 4 nodes 1 m apart from the origin
    soft::LightGrid moved = g;                         // the same values on nodes 2 m apart from (-3, 1, 2)
    moved.origin = {-3, 1, 2};
    moved.step = glm::vec3(2.0f);
    for (int i = 0; i < 300; ++i) {
      const glm::vec3 p(ux(rng), uy(rng), uz(rng));
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): the field 0.1 x + 0.2 y - 0.05 z + 0.3");
      CAPTURE(p);
      if (!CHECK_NEAR(ex05::lightMeshVisibility(g, p), field(p.x, p.y, p.z), 1e-4)) break;
      if (!CHECK_NEAR(ex05::lightMeshVisibility(moved, moved.origin + 2.0f * p), field(p.x, p.y, p.z), 1e-4)) break;
    }
  }

  TEST_CASE("ex05.7: three deltas and t on one of them, any weights; the 16-bit form's round trip") {
    std::mt19937_64 rng(test::seedFor("ex05.7 hidden"));
    std::uniform_real_distribution<double> depth(0.02, 0.98), weight(0.05, 1.0);
    for (int i = 0; i < 300; ++i) {
      double z[3] = {depth(rng), depth(rng), depth(rng)}, w[3] = {weight(rng), weight(rng), weight(rng)};
      std::sort(z, z + 3);
      if (z[1] - z[0] < 0.05 || z[2] - z[1] < 0.05) continue;  // well separated: B well conditioned
      const double sum = w[0] + w[1] + w[2];
      glm::dvec4 b(0.0);
      for (int k = 0; k < 3; ++k) {
        const double zk = z[k];
        b += w[k] / sum * glm::dvec4(zk, zk * zk, zk * zk * zk, zk * zk * zk * zk);
      }
      const int on = i % 3;  // t on one of the deltas: the solution is the distribution itself
      double lit = 0;
      for (int k = on; k < 3; ++k) lit += w[k] / sum;
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): depths ", z[0], ", ", z[1], ", ", z[2], ", weights ",
           w[0] / sum, ", ", w[1] / sum, ", ", w[2] / sum, ", t = depth ", on);
      if (!CHECK_NEAR(ex05::msmLitShare(b, z[on], 0.0), lit, 1e-5)) break;
    }
    // The 16-bit form read back: one caster at 0.4 shadows what is behind it and lights what is before.
    const glm::dvec4 stored = soft::msmDequantise(soft::msmQuantise(soft::msmMoments(0.4)));
    CHECK(ex05::msmLitShare(stored, 0.6, 3e-5) < 0.05);
    CHECK(ex05::msmLitShare(stored, 0.2, 3e-5) > 0.95);
  }
}

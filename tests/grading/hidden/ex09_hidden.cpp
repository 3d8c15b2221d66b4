// Hidden cases for lesson 09 (instructor tree only): the statement's formulas written out, and the
// reference for the bias, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/bias.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

TEST_SUITE("hidden") {
  TEST_CASE("ex09.1: random fields of view, aspects and a: the matrix entry by entry") {
    std::mt19937_64 rng(test::seedFor("ex09.1 hidden"));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const double fov = 0.2 + 2.6 * u(rng), aspect = 0.3 + 2 * u(rng), a = 1e-4 + 2 * u(rng);
      const double f = 1.0 / std::tan(fov / 2.0);
      glm::dmat4 want(0.0);
      want[0][0] = f / aspect;
      want[1][1] = f;
      want[3][2] = a;
      want[2][3] = -1.0;
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): fovY ", fov, ", aspect ", aspect, ", a ", a);
      if (!CHECK_NEAR(ex09::inverseProjection(fov, aspect, a), want, grading::relativeTolerance(1e-9))) break;
    }
  }

  TEST_CASE("ex09.2: random tight sets: every direction inside, none with room to spare") {
    std::mt19937_64 rng(test::seedFor("ex09.2 hidden"));
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 60; ++i) {
      // Directions on a known cone: the optimum is that cone when they surround its axis.
      const glm::dvec3 axis = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
      const glm::dvec3 t =
          glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
      const glm::dvec3 b = glm::cross(axis, t);
      const double half = 0.05 + 1.2 * u(rng);
      std::vector<glm::dvec3> d;
      for (int k = 0; k < 6; ++k) {
        const double phi = 2.0 * 3.14159265358979 * (k + 0.3 * u(rng)) / 6.0;
        d.push_back((std::cos(half) * axis + std::sin(half) * (std::cos(phi) * t + std::sin(phi) * b)) *
                    (0.2 + u(rng)));
      }
      d.push_back(axis * 3.0);  // an inner direction changes nothing
      INFO("random case ", i, " of 60 (seed ", test::seed(), "): 6 directions on a cone of half-angle ", half,
           " around ", grading::show(axis));
      const glm::dvec4 c = ex09::smallestEnclosingCone(d);
      if (!CHECK_NEAR(c, glm::dvec4(axis, half), 1e-6)) break;
    }
  }

  TEST_CASE("ex09.3: random directional lights: dot(n_f, D) >= 0") {
    std::mt19937_64 rng(test::seedFor("ex09.3 hidden"));
    std::normal_distribution<double> g(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
      const glm::dvec3 D(g(rng), g(rng), g(rng));
      bool ok = true;
      for (int f = 0; f < 6 && ok; ++f) {
        const double coord = (f % 2 == 0 ? 1.0 : -1.0) * D[f / 2];
        INFO("random case ", i, " of 300 (seed ", test::seed(), "): direction ", grading::show(D), ", face ", f);
        ok = CHECK_EXACT(ex09::cubeFaceVisible(f, glm::dvec4(D, 0.0)), coord >= 0.0);
      }
      if (!ok) break;
    }
  }

  TEST_CASE("ex09.4: random maps and points against the reference bias") {
    std::mt19937_64 rng(test::seedFor("ex09.4 hidden"));
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      glm::dmat4 M(1.0);  // a random, well-conditioned affine map
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) M[c][r] = (c == r ? 1.0 : 0.0) + 0.3 * u(rng);
      M[3] = glm::dvec4(u(rng), u(rng), u(rng), 1.0);
      const glm::dvec3 p(10 * u(rng), 10 * u(rng), 10 * u(rng)), L = glm::normalize(glm::dvec3(u(rng), u(rng), -2.0));
      const double a = 0.05 * (u(rng) + 1), b = 2 * (u(rng) + 1), S = 256.0 * (2 + int(4 * (u(rng) + 1)));
      const glm::dmat4 K = psm::texelOffsetMatrix(M, glm::dvec2(S));
      const glm::dvec3 expected = psm::biasedWorldPoint(p, L, a, b, psm::texelWorldSize(K, p));
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): a ", a, ", b ", b, ", map ", S);
      CAPTURE(M);
      CAPTURE(p);
      CAPTURE(L);
      if (!CHECK_NEAR(ex09::texelSizeBias(M, p, L, a, b, S), expected, grading::relativeTolerance(1e-9))) break;
    }
  }

  TEST_CASE("ex09.5: random ranges and angles against (z0 + sqrt(z0 z1)) / |sin gamma|") {
    std::mt19937_64 rng(test::seedFor("ex09.5 hidden"));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
      const double z0 = 0.001 + 20.0 * u(rng), z1 = z0 * (1.01 + 5000.0 * u(rng));
      const double gamma = i % 25 == 0 ? 0.0 : -3.1 + 6.2 * u(rng);  // now and then along the view
      const double s = std::abs(std::sin(gamma));
      const double expected = s == 0.0 ? std::numeric_limits<double>::infinity() : (z0 + std::sqrt(z0 * z1)) / s;
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): z0 ", z0, ", z1 ", z1, ", gamma ", gamma);
      if (!CHECK_NEAR(ex09::lispsmOptimalN(z0, z1, gamma), expected, grading::relativeTolerance(1e-9))) break;
    }
  }
}

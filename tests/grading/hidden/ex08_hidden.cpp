// Hidden cases for lesson 08 (instructor tree only): the classification written out from the
// exercise's statement, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using shadowlab::ex08::postProjectiveLight;

TEST_SUITE("hidden") {
  TEST_CASE("ex08.1: random cameras, point and directional lights against h = viewProj * light") {
    std::mt19937_64 rng(shadowlab::test::seedFor("ex08.1 hidden"));
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
      const double fov = 0.4 + 1.8 * (u(rng) * 0.5 + 0.5), n = 0.1 + (u(rng) + 1.0),
                   f = n * (20.0 + 300.0 * (u(rng) + 1));
      glm::dmat4 proj(0.0);
      const double t = 1.0 / std::tan(fov / 2.0);
      proj[0][0] = t / (1.0 + 0.5 * (u(rng) + 1));
      proj[1][1] = t;
      proj[2][2] = -(f + n) / (f - n);
      proj[3][2] = -2.0 * f * n / (f - n);
      proj[2][3] = -1.0;
      glm::dmat4 view(1.0);
      const double a = 3.0 * u(rng);
      view[0][0] = std::cos(a);
      view[2][0] = std::sin(a);
      view[0][2] = -std::sin(a);
      view[2][2] = std::cos(a);
      view[3] = glm::dvec4(8 * u(rng), 8 * u(rng), 8 * u(rng), 1.0);
      const glm::dmat4 vp = proj * view;
      const glm::dvec4 light = i % 3 == 0 ? glm::dvec4(glm::normalize(glm::dvec3(u(rng), u(rng), u(rng))), 0.0)
                                          : glm::dvec4(30 * u(rng), 30 * u(rng), 30 * u(rng), 1.0);
      const glm::dvec4 h = vp * light;
      glm::dvec4 expected;
      if (std::abs(h.w) <= 1e-9 * glm::length(glm::dvec3(h))) expected = glm::dvec4(glm::normalize(glm::dvec3(h)), 0.0);
      else expected = glm::dvec4(glm::dvec3(h) / h.w, h.w > 0 ? 1.0 : -1.0);
      INFO("random case ", i, " of 300 (seed ", shadowlab::test::seed(), ")");
      CAPTURE(vp);
      CAPTURE(light);
      if (!CHECK_NEAR(postProjectiveLight(vp, light), expected, shadowlab::grading::relativeTolerance(1e-9))) break;
    }
  }
}

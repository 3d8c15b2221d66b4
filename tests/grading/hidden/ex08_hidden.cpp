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

  TEST_CASE("ex08.2: random cameras and corners against max(z_view + zNear, 0)") {
    std::mt19937_64 rng(shadowlab::test::seedFor("ex08.2 hidden"));
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
      const double a = 3.0 * u(rng), b = 1.5 * u(rng), zNear = 0.01 + 3.0 * (u(rng) + 1.0);
      glm::dmat4 yaw(1.0), pitch(1.0);  // a rotation about y, then about x, and a translation
      yaw[0][0] = std::cos(a);
      yaw[2][0] = std::sin(a);
      yaw[0][2] = -std::sin(a);
      yaw[2][2] = std::cos(a);
      pitch[1][1] = std::cos(b);
      pitch[2][1] = -std::sin(b);
      pitch[1][2] = std::sin(b);
      pitch[2][2] = std::cos(b);
      glm::dmat4 view = pitch * yaw;
      view[3] = glm::dvec4(20 * u(rng), 20 * u(rng), 20 * u(rng), 1.0);
      std::vector<glm::dvec3> corners;
      double expected = 0.0;
      for (int k = 0; k < i % 9; ++k) {  // now and then none
        corners.push_back({40 * u(rng), 40 * u(rng), 40 * u(rng)});
        expected = std::max(expected, (view * glm::dvec4(corners.back(), 1.0)).z + zNear);
      }
      INFO("random case ", i, " of 300 (seed ", shadowlab::test::seed(), "): zNear ", zNear, ", ", corners.size(),
           " corners");
      CAPTURE(view);
      if (!CHECK_NEAR(shadowlab::ex08::virtualCameraShift(view, zNear, corners), expected,
                      shadowlab::grading::relativeTolerance(1e-9)))
        break;
    }
  }
}

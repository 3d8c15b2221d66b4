// Hidden cases for lesson 01 (instructor tree only; the handout leaves this folder out). They run
// in validity.ex01.* and when a submission is graded, with the seed the grader chooses. The
// randomised cases write the lecture's formulas out independently of the reference.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

using test::randomUnit;

TEST_SUITE("hidden") {
  TEST_CASE("ex01.1: random configurations against the lecture's formula") {
    std::mt19937_64 rng(test::seedFor("ex01.1 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 300; ++i) {
      const glm::vec3 N = randomUnit(rng), L = randomUnit(rng), V = randomUnit(rng);
      const glm::vec3 I(2 * u(rng), 2 * u(rng), 2 * u(rng)), kd(u(rng), u(rng), u(rng));
      const float fatt = u(rng), vis = u(rng), ks = u(rng), pw = 1 + 127 * u(rng);
      const float NdotL = glm::dot(N, L);
      glm::vec3 expected(0);
      if (NdotL > 0) {
        const glm::vec3 R = 2 * NdotL * N - L;
        expected = vis * fatt * I * (kd * NdotL + glm::vec3(ks * std::pow(std::max(glm::dot(R, V), 0.0f), pw)));
      }
      INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
      CAPTURE(N);
      CAPTURE(L);
      CAPTURE(V);
      CAPTURE(I);
      CAPTURE(kd);
      INFO("fatt = ", fatt, ", visibility = ", vis, ", ks = ", ks, ", shininess = ", pw);
      if (!CHECK_NEAR(ex01::lightContribution(N, L, V, I, fatt, vis, kd, ks, pw), expected, 1e-3)) break;
    }
  }

  TEST_CASE("ex01.2: composed with a perspective projection, points land in [0,1] after the divide") {
    // P: 90 degrees, n = 1, f = 10. The point (1, -1, -2) has clip (1, -1, 22/9 - 20/9, 2), so NDC
    // (0.5, -0.5, 1/9) and texture coordinates (0.75, 0.25, 0.5 + 1/18).
    glm::mat4 P(0.0f);
    P[0][0] = 1;
    P[1][1] = 1;
    P[2][2] = -11.0f / 9.0f;
    P[3][2] = -20.0f / 9.0f;
    P[2][3] = -1;
    const glm::vec4 clip = P * glm::vec4(1, -1, -2, 1);
    const glm::vec4 t = ex01::ndcToTexture() * clip;
    CAPTURE(clip);
    CHECK_NEAR(glm::vec3(t) / t.w, glm::vec3(0.75f, 0.25f, 0.5f + 0.5f / 9.0f), 1e-5);
  }

  TEST_CASE("ex01.3: random coefficients and distances against 1 / (c0 + c1 d + c2 d^2)") {
    std::mt19937_64 rng(test::seedFor("ex01.3 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 200; ++i) {
      const glm::vec3 c(0.05f + u(rng), u(rng), u(rng));
      const float d = 20 * u(rng);
      INFO("random case ", i, " of 200 (seed ", test::seed(), ")");
      CAPTURE(c);
      CAPTURE(d);
      const float expected = 1.0f / (c.x + c.y * d + c.z * d * d);
      if (!CHECK_NEAR(ex01::attenuation(c, d), expected, grading::relativeTolerance(1e-5))) break;
    }
  }

  TEST_CASE("ex01.4: random cones and angles against the smoothstep on the cosines") {
    std::mt19937_64 rng(test::seedFor("ex01.4 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 200; ++i) {
      const float inner = 0.05f + 0.6f * u(rng), outer = inner + 0.02f + 0.5f * u(rng);
      const float angle = 1.3f * u(rng), cosAngle = std::cos(angle);
      const float t = std::clamp((cosAngle - std::cos(outer)) / (std::cos(inner) - std::cos(outer)), 0.0f, 1.0f);
      INFO("random case ", i, " of 200 (seed ", test::seed(), ")");
      INFO("cosAngle = ", cosAngle, " (", angle, " rad), inner = ", inner, ", outer = ", outer);
      if (!CHECK_NEAR(ex01::spotFactor(cosAngle, inner, outer), t * t * (3 - 2 * t), 1e-4)) break;
    }
  }
}

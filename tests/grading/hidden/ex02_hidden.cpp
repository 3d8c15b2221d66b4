// Hidden cases for lesson 02 (instructor tree only): formulas written out independently of the
// reference, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

TEST_SUITE("hidden") {
  TEST_CASE("ex02.1: random light cameras: T = remap * P * V, with w kept") {
    std::mt19937_64 rng(test::seedFor("ex02.1 hidden"));
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 100; ++i) {
      const glm::vec3 eye(u(rng) * 20, 8 + 6 * u(rng), u(rng) * 20);
      const glm::mat4 V = glm::lookAt(eye, glm::vec3(2 * u(rng), 0, 2 * u(rng)), glm::vec3(0, 1, 0));
      const glm::mat4 P = glm::perspective(0.4f + 0.6f * (u(rng) + 1), 0.5f + (u(rng) + 1), 0.2f, 80.0f);
      const glm::vec3 p(u(rng) * 5, 2 * u(rng), u(rng) * 5);
      const glm::vec4 clip = P * V * glm::vec4(p, 1);
      const glm::vec4 expected(0.5f * (clip.x + clip.w), 0.5f * (clip.y + clip.w), 0.5f * (clip.z + clip.w), clip.w);
      INFO("random case ", i, " of 100 (seed ", test::seed(), ")");
      CAPTURE(P);
      CAPTURE(V);
      CAPTURE(p);
      if (!CHECK_NEAR(ex02::shadowTextureMatrix(P, V) * glm::vec4(p, 1), expected, grading::relativeTolerance(1e-3)))
        break;
    }
  }

  TEST_CASE("ex02.2: random depths and biases: lit exactly when depth - bias <= stored") {
    std::mt19937_64 rng(test::seedFor("ex02.2 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 300; ++i) {
      const float d = u(rng), s = u(rng), b = 0.05f * u(rng);
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): depth ", d, ", stored ", s, ", bias ", b);
      if (!CHECK_NEAR(ex02::depthCompare(d, s, b), d - b <= s ? 1.0f : 0.0f, 0)) break;
    }
  }

  TEST_CASE("ex02.3: random maps against the nearest-texel rule") {
    std::mt19937_64 rng(test::seedFor("ex02.3 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    bool ok = true;
    for (int i = 0; i < 50 && ok; ++i) {
      const int w = 1 + int(u(rng) * 16), h = 1 + int(u(rng) * 16);
      std::vector<float> d(std::size_t(w * h));
      for (float& x : d) x = u(rng);
      const shadow::DepthMap m(w, h, d);
      for (int k = 0; k < 20 && ok; ++k) {
        const glm::vec3 uvz(u(rng) * 0.999f, u(rng) * 0.999f, u(rng));
        const int x = int(uvz.x * float(w)), y = int(uvz.y * float(h));
        const float expected = uvz.z - 0.01f <= d[std::size_t(y * w + x)] ? 1.0f : 0.0f;
        INFO("random map ", i, " (", w, "x", h, "), lookup ", k, " (seed ", test::seed(), ")");
        CAPTURE(uvz);
        ok = CHECK_NEAR(ex02::shadowLookup(m, uvz, 0.01f), expected, 0);
      }
    }
  }
}

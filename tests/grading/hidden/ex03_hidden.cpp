// Hidden cases for lesson 03 (instructor tree only): the rules written out independently of the
// reference, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

TEST_SUITE("hidden") {
  TEST_CASE("ex03.1: random angles and coefficients against min(c + s tan(theta), max)") {
    std::mt19937_64 rng(test::seedFor("ex03.1 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 200; ++i) {
      const float c = 0.005f * u(rng), s = 0.02f * u(rng), maxBias = 0.005f + 0.05f * u(rng);
      const float cosTheta = 1.2f * u(rng) - 0.2f;  // some facing away
      const float expected =
          cosTheta <= 0 ? maxBias : std::min(c + s * std::sqrt(1 - cosTheta * cosTheta) / cosTheta, maxBias);
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): constant ", c, ", slope ", s, ", cosTheta ", cosTheta,
           ", maxBias ", maxBias);
      if (!CHECK_NEAR(ex03::slopeScaledBias(c, s, cosTheta, maxBias), expected, 1e-6)) break;
    }
  }

  TEST_CASE("ex03.2: random positions against the bilinear weights of t = texel - 0.5") {
    std::mt19937_64 rng(test::seedFor("ex03.2 hidden"));
    std::uniform_real_distribution<float> u(-4, 260);
    for (int i = 0; i < 300; ++i) {
      const glm::vec2 p(u(rng), u(rng));
      const glm::vec2 t = p - 0.5f, f = t - glm::floor(t);
      const glm::vec4 expected((1 - f.x) * (1 - f.y), f.x * (1 - f.y), (1 - f.x) * f.y, f.x * f.y);
      INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
      CAPTURE(p);
      if (!CHECK_NEAR(ex03::bilinearPcfWeights(p), expected, 1e-4)) break;
    }
  }

  TEST_CASE("ex03.3: random directions: the major axis, + before -") {
    std::mt19937_64 rng(test::seedFor("ex03.3 hidden"));
    std::normal_distribution<float> n;
    for (int i = 0; i < 300; ++i) {
      glm::vec3 d(n(rng), n(rng), n(rng));
      if (i % 10 == 0) d[i % 3] = 0;  // a zero component now and then
      const glm::vec3 a = glm::abs(d);
      const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
      INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
      CAPTURE(d);
      if (!CHECK_EXACT(ex03::cubeFace(d), 2 * axis + (d[axis] < 0 ? 1 : 0))) break;
    }
  }

  TEST_CASE("ex03.4: random boxes, views and lights against the separating-plane rule") {
    std::mt19937_64 rng(test::seedFor("ex03.4 hidden"));
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 300; ++i) {
      const glm::vec3 lo(8 * u(rng), 8 * u(rng), 8 * u(rng));
      const shadow::ConvexVolume view = shadow::volumeFromBox({lo, lo + glm::vec3(2 + 6 * (u(rng) + 1))});
      const glm::vec3 c(20 * u(rng), 20 * u(rng), 20 * u(rng));
      const Aabb box{c - 0.5f - glm::abs(u(rng)), c + 0.5f + glm::abs(u(rng))};
      const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng) - 0.5f, u(rng)));
      bool expected = true;
      for (const glm::vec4& plane : view.planes) {
        const glm::vec3 n(plane);
        const glm::vec3 far(n.x >= 0 ? box.max.x : box.min.x, n.y >= 0 ? box.max.y : box.min.y,
                            n.z >= 0 ? box.max.z : box.min.z);
        if (glm::dot(n, far) + plane.w < 0 && glm::dot(n, dir) <= 0) expected = false;
      }
      INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
      CAPTURE(box.min);
      CAPTURE(box.max);
      CAPTURE(dir);
      if (!CHECK_EXACT(ex03::casterMayShadow(box, view, dir), expected)) break;
    }
  }

  TEST_CASE("ex03.5: random lights: tight bounds of the receivers in light space, texel size from them") {
    std::mt19937_64 rng(test::seedFor("ex03.5 hidden"));
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 40; ++i) {
      const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), -1.0f + 0.6f * u(rng), u(rng)));
      std::vector<glm::vec3> receivers;
      for (int k = 0; k < 8; ++k) receivers.push_back({30 * u(rng), 3 * u(rng), 30 * u(rng)});
      const std::vector<Aabb> casters;
      const int size = 512 << (i % 3);
      const shadow::OrthoFit fit = ex03::fitOrthographic(dir, receivers, casters, size, false);
      const glm::mat4 lightView = shadow::lightViewAlong(glm::vec3(0), dir);
      glm::vec3 lo(1e30f), hi(-1e30f);
      for (const glm::vec3& r : receivers) {
        const glm::vec3 q(lightView * glm::vec4(r, 1));
        lo = glm::min(lo, q), hi = glm::max(hi, q);
      }
      INFO("random case ", i, " of 40 (seed ", test::seed(), "), map ", size);
      CAPTURE(dir);
      if (!CHECK_NEAR(fit.texelWorld, std::max(hi.x - lo.x, hi.y - lo.y) / float(size), 1e-6)) break;
      const glm::mat4 m = fit.projection * fit.view;
      bool ok = true;
      for (const glm::vec3& r : receivers) {
        const glm::vec4 q = m * glm::vec4(r, 1);
        ok = ok && std::abs(q.x) <= 1.001f && std::abs(q.y) <= 1.001f && std::abs(q.z) <= 1.0f;
      }
      if (!CHECK_TRUE(ok)) break;
    }
  }
}

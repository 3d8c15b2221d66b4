// Hidden cases for lesson 04 (instructor tree only): the rules written out independently of the
// reference where they are short, the reference itself where they are not, with the seed the
// grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "algorithms/shadow_volume.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using volume::StencilOp;

TEST_SUITE("hidden") {
  TEST_CASE("ex04.1: random edges against the plane test") {
    std::mt19937_64 rng(test::seedFor("ex04.1 hidden"));
    std::uniform_real_distribution<float> u(-5, 5);
    for (int i = 0; i < 500; ++i) {
      const glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng)),
          d(u(rng), u(rng), u(rng));
      const glm::vec4 L(u(rng), u(rng), u(rng), i % 2 ? 1.0f : 0.0f);
      auto side = [&](glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
        return glm::dot(glm::cross(p1 - p0, p2 - p0), glm::vec3(L) - p0 * L.w) > 0.0f;
      };
      INFO("random case ", i, " of 500 (seed ", test::seed(), ")");
      CAPTURE(a);
      CAPTURE(b);
      CAPTURE(c);
      CAPTURE(d);
      CAPTURE(L);
      if (!CHECK_EXACT(ex04::isSilhouette(a, b, c, d, L), side(a, b, c) != side(b, a, d))) break;
    }
  }

  TEST_CASE("ex04.2: random fields of view, aspects, near planes and epsilons, entry by entry") {
    std::mt19937_64 rng(test::seedFor("ex04.2 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 100; ++i) {
      const float fov = 0.3f + 2.5f * u(rng), aspect = 0.5f + 2 * u(rng), n = 0.01f + 2 * u(rng), eps = 1e-3f * u(rng);
      const float f = 1.0f / std::tan(fov / 2);
      glm::mat4 e(0.0f);
      e[0][0] = f / aspect;
      e[1][1] = f;
      e[2][2] = eps - 1;
      e[2][3] = -1;
      e[3][2] = n * (eps - 2);
      INFO("random case ", i, " of 100 (seed ", test::seed(), "): fovY ", fov, ", aspect ", aspect, ", near ", n,
           ", epsilon ", eps);
      if (!CHECK_NEAR(ex04::infinitePerspective(fov, aspect, n, eps), e, grading::relativeTolerance(1e-5))) break;
    }
  }

  TEST_CASE("ex04.3: z-fail is z-pass with front and back, pass and fail exchanged") {
    const volume::StencilOps pass = ex04::stencilOps(false), fail = ex04::stencilOps(true);
    INFO("StencilOp: 0 Keep, 1 IncrWrap, 2 DecrWrap (volume::StencilOp)");
    CHECK_EXACT(fail.back.depthFail, pass.front.depthPass);
    CHECK_EXACT(fail.front.depthFail, pass.back.depthPass);
    CHECK_EXACT(pass.front.depthPass, StencilOp::IncrWrap);  // counts wrap: order of faces does not matter
    CHECK_EXACT(fail.back.depthFail, StencilOp::IncrWrap);
    CHECK_EXACT(fail.front.depthPass, StencilOp::Keep);
    CHECK_EXACT(pass.back.depthFail, StencilOp::Keep);
  }

  TEST_CASE("ex04.4: random boxes and lights against the reference hull test") {
    std::mt19937_64 rng(test::seedFor("ex04.4 hidden"));
    std::uniform_real_distribution<float> u(-1, 1), t01(0, 1);
    volume::NearRect r;
    r.corners[0] = {-0.8f, -0.45f, -0.5f};
    r.corners[1] = {0.8f, -0.45f, -0.5f};
    r.corners[2] = {0.8f, 0.45f, -0.5f};
    r.corners[3] = {-0.8f, 0.45f, -0.5f};
    int trues = 0;
    for (int i = 0; i < 400; ++i) {
      const glm::vec4 L = i % 2 ? glm::vec4(12 * u(rng), 12 * u(rng), 12 * u(rng), 1)
                                : glm::vec4(glm::normalize(glm::vec3(u(rng), u(rng), u(rng))), 0);
      const glm::vec3 c(6 * u(rng), 6 * u(rng), 6 * u(rng));
      const float h = 0.1f + 2 * t01(rng);
      Aabb b;
      b.extend(c - glm::vec3(h));
      b.extend(c + glm::vec3(h));
      const bool expected = volume::volumeMayReachNearPlane(b, r, L);
      trues += expected;
      INFO("random case ", i, " of 400 (seed ", test::seed(), "): near rectangle (+-0.8, +-0.45, -0.5)");
      CAPTURE(L);
      CAPTURE(b.min);
      CAPTURE(b.max);
      if (!CHECK_EXACT(ex04::volumeMayReachNearPlane(b, r, L), expected)) break;
    }
    CHECK(trues > 20);
  }
}

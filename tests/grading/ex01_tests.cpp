// Graders for lesson 01 (make grade LESSON=01): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases compare with the reference implementation (compiled into
// the course library). More cases, with seeds the grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "algorithms/lighting.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

using test::randomUnit;

TEST_CASE("ex01.1: head-on light, eye along the normal: kd + ks") {
  // N = L = V = +z: N.L = 1, R = +z, R.V = 1 -> 0.5 * 1 + 0.5 * 1^10 = 1.
  const glm::vec3 z(0, 0, 1);
  CHECK_NEAR(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 1, glm::vec3(0.5f), 0.5f, 10), glm::vec3(1), 1e-4);
}

TEST_CASE("ex01.1: light at 60 degrees, with colour, attenuation and exponent") {
  // L = (sin 60, 0, cos 60): N.L = 0.5; R = reflect(-L, N) = (-sin 60, 0, 0.5): R.V = 0.5 for V = +z.
  // kd = (1,0,0), ks = 1, pow 2: (0.5 + 0.25, 0.25, 0.25); times I = 2 and f_att = 0.5 -> (0.75, 0.25, 0.25).
  const glm::vec3 L(std::sin(glm::radians(60.0f)), 0, 0.5f);
  CAPTURE(L);
  CHECK_NEAR(ex01::lightContribution({0, 0, 1}, L, {0, 0, 1}, glm::vec3(2), 0.5f, 1, {1, 0, 0}, 1, 2),
             glm::vec3(0.75f, 0.25f, 0.25f), 1e-4);
}

TEST_CASE("ex01.1: visibility scales the whole term, a shadowed point gets nothing") {
  const glm::vec3 z(0, 0, 1);
  CHECK_NEAR(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 0.5f, glm::vec3(0.5f), 0.5f, 10), glm::vec3(0.5f), 1e-4);
  CHECK_NEAR(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 0.0f, glm::vec3(0.5f), 0.5f, 10), glm::vec3(0), 1e-4);
}

TEST_CASE("ex01.1: no highlight behind the terminator, full light in front of it") {
  // L = -z faces away (N.L = -1); with V = -z the mirror direction R.V would be 1, but a surface
  // the light cannot reach must stay black. The same light moved in front (L = +z) gives
  // kd + ks = (0.5 + 1, ...) = 1.5: a function that returns black everywhere fails here too.
  CHECK_NEAR(ex01::lightContribution({0, 0, 1}, {0, 0, -1}, {0, 0, -1}, glm::vec3(1), 1, 1, glm::vec3(0.5f), 1, 4),
             glm::vec3(0), 1e-4);
  CHECK_NEAR(ex01::lightContribution({0, 0, 1}, {0, 0, 1}, {0, 0, 1}, glm::vec3(1), 1, 1, glm::vec3(0.5f), 1, 4),
             glm::vec3(1.5f), 1e-4);
}

TEST_CASE("ex01.1: random configurations against the reference") {
  std::mt19937_64 rng(test::seedFor("ex01.1"));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 N = randomUnit(rng), L = randomUnit(rng), V = randomUnit(rng);
    const glm::vec3 I(u(rng), u(rng), u(rng)), kd(u(rng), u(rng), u(rng));
    const float fatt = u(rng), vis = u(rng), ks = u(rng), pw = 1 + 63 * u(rng);
    INFO("random case ", i, " of 200 (seed ", test::seed(), ")");
    CAPTURE(N);
    CAPTURE(L);
    CAPTURE(V);
    CAPTURE(I);
    CAPTURE(kd);
    INFO("fatt = ", fatt, ", visibility = ", vis, ", ks = ", ks, ", shininess = ", pw);
    if (!CHECK_NEAR(ex01::lightContribution(N, L, V, I, fatt, vis, kd, ks, pw),
                    lighting::lightContribution(N, L, V, I, fatt, vis, kd, ks, pw), 1e-3))
      break;
  }
}

TEST_CASE("ex01.2: the corners and the centre of NDC land on [0,1]^3") {
  const glm::mat4 m = ex01::ndcToTexture();
  CAPTURE(m);
  CHECK_NEAR(glm::vec3(m * glm::vec4(-1, -1, -1, 1)), glm::vec3(0), 1e-5);
  CHECK_NEAR(glm::vec3(m * glm::vec4(1, 1, 1, 1)), glm::vec3(1), 1e-5);
  CHECK_NEAR(glm::vec3(m * glm::vec4(0, 0, 0, 1)), glm::vec3(0.5f), 1e-5);
  CHECK_NEAR(glm::vec3(m * glm::vec4(1, -1, 0, 1)), glm::vec3(1, 0, 0.5f), 1e-5);
}

TEST_CASE("ex01.2: it is affine and keeps w, so it composes with a projection") {
  // In homogeneous form the remap must scale x, y, z by 0.5 and add 0.5 w: (x, y, z, w) ->
  // (0.5 x + 0.5 w, ..., w). A point (2, 2, 2, 2) (NDC (1,1,1)) maps to (2, 2, 2, 2); the
  // translation lives in column 3.
  const glm::mat4 m = ex01::ndcToTexture();
  CHECK_NEAR(m * glm::vec4(2, 2, 2, 2), glm::vec4(2), 1e-5);
  CHECK_NEAR(m * glm::vec4(0, 0, 0, 4), glm::vec4(2, 2, 2, 4), 1e-5);
  CHECK_NEAR(m[0][0], 0.5f, 1e-6);
  CHECK_NEAR(m[3][0], 0.5f, 1e-6);
}

TEST_CASE("ex01.3: attenuation by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  CHECK_NEAR(ex01::attenuation({1, 0.5f, 0.25f}, 2), 1.0f / 3.0f, 1e-6);  // 1 + 1 + 1
  CHECK_NEAR(ex01::attenuation({0, 0, 1}, 4), 1.0f / 16.0f, 1e-6);        // inverse square
  CHECK_NEAR(ex01::attenuation({0, 2, 0}, 5), 0.1f, 1e-6);
  CHECK_NEAR(ex01::attenuation({1, 0, 0}, 7), 1.0f, 1e-6);  // constant only: no fall-off
}

TEST_CASE("ex01.4: the spot cone: full inside, none outside, smooth between") {
  // At 0.4 rad: t = (cos .4 - cos .5) / (cos .3 - cos .5) = 0.559180, t^2 (3 - 2t) = 0.588355.
  CHECK_NEAR(ex01::spotFactor(std::cos(0.4f), 0.3f, 0.5f), 0.588355f, 1e-4);
  CHECK_NEAR(ex01::spotFactor(std::cos(0.6f), 0.3f, 0.5f), 0.0f, 1e-6);
  CHECK_NEAR(ex01::spotFactor(std::cos(0.5f), 0.3f, 0.5f), 0.0f, 1e-6);
  CHECK_NEAR(ex01::spotFactor(1.0f, 0.3f, 0.5f), 1.0f, 1e-6);
}

// Graders for lesson 01 (ctest -L ex01). Expected values are worked out by hand in the comments;
// the randomised cases compare against the formula written out independently here.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(eps)));
}
glm::vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<float> n;
  glm::vec3 v;
  do v = {n(rng), n(rng), n(rng)};
  while (glm::length(v) < 1e-3f);
  return glm::normalize(v);
}
}  // namespace

TEST_CASE("ex01.1: head-on light, eye along the normal: kd + ks") {
  // N = L = V = +z: N.L = 1, R = +z, R.V = 1 -> 0.5 * 1 + 0.5 * 1^10 = 1.
  const glm::vec3 z(0, 0, 1);
  CHECK(near(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 1, glm::vec3(0.5f), 0.5f, 10), glm::vec3(1)));
}

TEST_CASE("ex01.1: light at 60 degrees, with colour, attenuation and exponent") {
  // L = (sin 60, 0, cos 60): N.L = 0.5; R = reflect(-L, N) = (-sin 60, 0, 0.5): R.V = 0.5 for V = +z.
  // kd = (1,0,0), ks = 1, pow 2: (0.5 + 0.25, 0.25, 0.25); times I = 2 and f_att = 0.5 -> (0.75, 0.25, 0.25).
  const glm::vec3 L(std::sin(glm::radians(60.0f)), 0, 0.5f);
  const glm::vec3 r = ex01::lightContribution({0, 0, 1}, L, {0, 0, 1}, glm::vec3(2), 0.5f, 1, {1, 0, 0}, 1, 2);
  CHECK(near(r, {0.75f, 0.25f, 0.25f}));
}

TEST_CASE("ex01.1: visibility scales the whole term, a shadowed point gets nothing") {
  const glm::vec3 z(0, 0, 1);
  CHECK(near(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 0.5f, glm::vec3(0.5f), 0.5f, 10), glm::vec3(0.5f)));
  CHECK(near(ex01::lightContribution(z, z, z, glm::vec3(1), 1, 0.0f, glm::vec3(0.5f), 0.5f, 10), glm::vec3(0)));
}

TEST_CASE("ex01.1: no highlight behind the terminator") {
  // L = -z faces away (N.L = -1); with V = -z the mirror direction R.V would be 1, but a surface
  // the light cannot reach must stay black.
  CHECK(near(ex01::lightContribution({0, 0, 1}, {0, 0, -1}, {0, 0, -1}, glm::vec3(1), 1, 1, glm::vec3(0.5f), 1, 4),
             glm::vec3(0)));
}

TEST_CASE("ex01.1: random configurations against the lecture's formula") {
  std::mt19937_64 rng(test::seedFor("ex01.1"));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 N = randomUnit(rng), L = randomUnit(rng), V = randomUnit(rng);
    const glm::vec3 I(u(rng), u(rng), u(rng)), kd(u(rng), u(rng), u(rng));
    const float fatt = u(rng), vis = u(rng), ks = u(rng), pw = 1 + 63 * u(rng);
    const float NdotL = glm::dot(N, L);
    glm::vec3 expected(0);
    if (NdotL > 0) {
      const glm::vec3 R = 2 * NdotL * N - L;
      expected = vis * fatt * I * (kd * NdotL + glm::vec3(ks * std::pow(std::max(glm::dot(R, V), 0.0f), pw)));
    }
    INFO("seed ", test::seed(), " case ", i);
    CHECK(near(ex01::lightContribution(N, L, V, I, fatt, vis, kd, ks, pw), expected, 1e-3f));
  }
}

TEST_CASE("ex01.2: the corners and the centre of NDC land on [0,1]^3") {
  const glm::mat4 m = ex01::ndcToTexture();
  CHECK(near(glm::vec3(m * glm::vec4(-1, -1, -1, 1)), glm::vec3(0)));
  CHECK(near(glm::vec3(m * glm::vec4(1, 1, 1, 1)), glm::vec3(1)));
  CHECK(near(glm::vec3(m * glm::vec4(0, 0, 0, 1)), glm::vec3(0.5f)));
  CHECK(near(glm::vec3(m * glm::vec4(1, -1, 0, 1)), glm::vec3(1, 0, 0.5f)));
}

TEST_CASE("ex01.2: it is affine and keeps w, so it composes with a projection") {
  // In homogeneous form the remap must scale x, y, z by 0.5 and add 0.5 w: (x, y, z, w) ->
  // (0.5 x + 0.5 w, ..., w). A point (2, 2, 2, 2) (NDC (1,1,1)) maps to (2, 2, 2, 2).
  const glm::mat4 m = ex01::ndcToTexture();
  const glm::vec4 r = m * glm::vec4(2, 2, 2, 2);
  CHECK(r.w == doctest::Approx(2));
  CHECK(near(glm::vec3(r), glm::vec3(2)));
  CHECK(m[0][0] == doctest::Approx(0.5f));
  CHECK(m[3][0] == doctest::Approx(0.5f));  // translation lives in column 3
}

TEST_CASE("ex01.3: attenuation by hand") {
  CHECK(ex01::attenuation({1, 0, 0}, 7) == doctest::Approx(1.0f));
  CHECK(ex01::attenuation({1, 0.5f, 0.25f}, 2) == doctest::Approx(1.0f / 3.0f));  // 1 + 1 + 1
  CHECK(ex01::attenuation({0, 0, 1}, 4) == doctest::Approx(1.0f / 16.0f));        // inverse square
  CHECK(ex01::attenuation({0, 2, 0}, 5) == doctest::Approx(0.1f));
}

TEST_CASE("ex01.4: the spot cone: full inside, none outside, smooth between") {
  CHECK(ex01::spotFactor(1.0f, 0.3f, 0.5f) == doctest::Approx(1.0f));
  CHECK(ex01::spotFactor(std::cos(0.6f), 0.3f, 0.5f) == doctest::Approx(0.0f));
  // At 0.4 rad: t = (cos .4 - cos .5) / (cos .3 - cos .5) = 0.559180, t^2 (3 - 2t) = 0.588355.
  CHECK(ex01::spotFactor(std::cos(0.4f), 0.3f, 0.5f) == doctest::Approx(0.588355f).epsilon(1e-4));
  CHECK(ex01::spotFactor(std::cos(0.5f), 0.3f, 0.5f) == doctest::Approx(0.0f));
}

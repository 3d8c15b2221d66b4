#pragma once
// The hidden renders' random placements, shared by the lessons' hidden GLSL cases: randomRender
// (a render whose arguments the grader may draw again), and a sun from a random azimuth at least
// `minDown` down with a random camera yaw, as the lesson's --set arguments.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"

namespace shadowlab::glslcases {

inline std::vector<std::string> randomSunAndCamera(std::mt19937_64& rng, float minDown) {
  std::uniform_real_distribution<float> u(0, 1);
  const float a = 6.2832f * u(rng);
  const glm::vec3 sun = glm::normalize(glm::vec3(std::cos(a), -(minDown + u(rng)), std::sin(a)));
  return {"--set", "light0.direction=" + glslFloat(sun.x) + " " + glslFloat(sun.y) + " " + glslFloat(sun.z), "--set",
          "camera.yaw=" + glslFloat(6.2832f * u(rng))};
}

// A hidden render at a random placement: draw(generator) gives the lesson's arguments. The render
// keeps a seed of its own, drawn from rng, so the grader can draw again (GlslRender::redraw) when
// the reference's render of a placement shows too little to grade; every draw follows from the
// grading run's seed. Measured against the ground truth, the tolerances of every lesson's renders.
template <class Draw>
GlslRender randomRender(std::mt19937_64& rng, std::string name, Draw draw) {
  const std::uint64_t seed = rng();
  auto args = [seed, draw](int attempt) {
    std::mt19937_64 r(seed + 0x9E3779B97F4A7C15ull * std::uint64_t(attempt));
    return draw(r);
  };
  GlslRender render{std::move(name), args(0), 8, 0.001, 0.05, true};
  render.redraw = args;
  return render;
}

}  // namespace shadowlab::glslcases

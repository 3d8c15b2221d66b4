// Hidden GLSL cases for lesson 07 (instructor tree only): random descents, and the lesson
// rendered from random cameras and suns, with the seed the grader chooses.
#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "../glsl/ex07_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex07 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex07glsl::randomDescent(rng, "ex07.5: hidden random descents " + std::to_string(i)));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 2; ++i) {
    const float a = 6.2832f * u(rng);
    const glm::vec3 sun = glm::normalize(glm::vec3(std::cos(a), -(0.6f + u(rng)), std::sin(a)));
    h.renders.push_back(
        {"ex07.5: hidden render " + std::to_string(i) + ": a random sun and camera",
         {"--set", "light0.direction=" + glslFloat(sun.x) + " " + glslFloat(sun.y) + " " + glslFloat(sun.z), "--set",
          "camera.yaw=" + glslFloat(6.2832f * u(rng)), "--set", "levels=" + std::to_string(1 + i + int(2 * u(rng)))},
         8,
         0.001,
         0.05,
         true});
  }
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("07_hybrid_maps", hidden), true);
}  // namespace

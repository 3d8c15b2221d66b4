// Hidden GLSL cases for lesson 03 (instructor tree only): random kernels up to 9 x 9, and the
// lesson rendered from random camera and sun placements with random kernels, with the seed the
// grader chooses.
#include <random>

#include <glm/glm.hpp>

#include "../glsl/ex03_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "random_view.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex03 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex03glsl::randomKernels(rng, "ex03.6: hidden random kernels " + std::to_string(i), 9));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex03.6: hidden render " + std::to_string(i) + ": a random sun, camera and kernel",
        [i](std::mt19937_64& r) {
          std::uniform_real_distribution<float> u(0, 1);
          const float a = 6.2832f * u(r);
          const glm::vec3 sun = glm::normalize(glm::vec3(std::cos(a), -(1.0f + u(r)), std::sin(a)));
          const std::string size = std::to_string(3 + 2 * (i + int(2 * u(r))));  // 3..7
          return std::vector<std::string>{
              "--set", "filter=pcf_nxn",
              "--set", "pcf.size=" + size,
              "--set", "light0.direction=" + glslFloat(sun.x) + " " + glslFloat(sun.y) + " " + glslFloat(sun.z),
              "--set", "camera.yaw=" + glslFloat(6.2832f * u(r)),
              "--set", std::string("bias.receiver_plane=") + (u(r) < 0.5f ? "true" : "false")};
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("03_shadow_quality", hidden), true);
}  // namespace

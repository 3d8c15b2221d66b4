// Hidden GLSL cases for lesson 06 (instructor tree only): random footprints and coordinates over
// every level, and the lesson rendered from random views, with the seed the grader chooses.
#include <random>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;
using shadowlab::glslVec;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex06 GLSL hidden"));
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < 24; ++i) {
    const float scale = std::pow(10.0f, -3.0f + 2.5f * (u(rng) + 1) / 2);  // magnified to heavily minified
    const glm::vec2 dx(scale * u(rng), scale * u(rng)), dy(scale * u(rng), scale * u(rng));
    h.cases.push_back({"ex06.8: hidden random derivatives " + std::to_string(i),
                       "vec4(ripLevelOfDetail(" + glslVec(dx) + ", " + glslVec(dy) + ", ivec2(" +
                           std::to_string(16 << (i % 6)) + ", " + std::to_string(8 << ((i / 6) % 5)) + ")), 0, 0)",
                       std::nullopt, 1e-4f, 2});
  }
  for (int i = 0; i < 24; ++i) {
    const glm::vec2 uv(6 * u(rng), 6 * u(rng));
    const std::string level = "ivec2(" + std::to_string(rng() % 4) + ", " + std::to_string(rng() % 3) + ")";
    h.cases.push_back({"ex06.9: hidden random coordinates " + std::to_string(i),
                       "ripBilinear(" + level + ", " + glslVec(uv) + ")", std::nullopt, 1e-5f, 4});
  }
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(
        {"ex06.9: hidden render " + std::to_string(i) + ": RIP maps from a random view",
         {"--preset", "rip_vs_mip", "--set", "camera.yaw=" + glslFloat(3.1416f * u(rng)), "--set",
          "camera.pitch=" + glslFloat(0.1f + 0.25f * (u(rng) + 1)), "--set", "filter.lod_bias=" + glslFloat(u(rng))},
         8,
         0.001,
         0.05,
         false,
         true});
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("06_texture_filtering", hidden), true);
}  // namespace

// Hidden GLSL cases for lesson 02 (instructor tree only): random lookups on a random map, and the
// lesson rendered from random camera and light placements, with the seed the grader chooses.
#include <random>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"
#include "random_view.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;
using shadowlab::glslVec;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex02 GLSL hidden"));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 24; ++i) {
    std::string e = "vec4(";
    for (int k = 0; k < 4; ++k) {
      const float s = u(rng), b = 0.05f * u(rng);
      const float d = k == 0 ? s + b + 0.001f + 0.5f * u(rng) : s + 0.1f * (u(rng) - 0.5f);
      e += (k ? ", " : "") + std::string("shadowCompare(") + glslFloat(d) + ", " + glslFloat(s) + ", " + glslFloat(b) +
           ")";
    }
    h.cases.push_back({"ex02.4: hidden random comparisons " + std::to_string(i), e + ")", std::nullopt, 0, 4});
  }
  for (int i = 0; i < 24; ++i) {
    std::string e = "vec4(";
    for (int k = 0; k < 4; ++k) {
      const float w = k == 2 ? -(0.2f + u(rng)) : 0.2f + 3 * u(rng);  // one behind the light
      glm::vec4 c(w * (1.4f * u(rng) - 0.2f), w * (1.4f * u(rng) - 0.2f), w * 1.2f * u(rng), w);
      if (k == 3) c = w * glm::vec4(0.25f * u(rng), 0.5f * u(rng), 0.3f + 0.6f * u(rng), 1);  // texel (0,0): shadowed
      e += (k ? ", " : "") + std::string("shadowLookup(uCaseMap, ") + glslVec(c) + ", " + glslFloat(0.05f * u(rng)) +
           ")";
    }
    h.cases.push_back({"ex02.5: hidden random lookups " + std::to_string(i), e + ")", std::nullopt, 0, 4,
                       "uCaseMap: 4x2, row 0 (v < 0.5) 0.2 0.8 0.8 0.8, row 1 0.8 0.8 0.3 0.8"});
  }
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex02.5: hidden render " + std::to_string(i) + ": a random spot and camera (compare=manual)",
        [](std::mt19937_64& r) {
          std::uniform_real_distribution<float> v(0, 1);
          const float a = 6.2832f * v(r);
          const glm::vec3 light(18 * std::cos(a), 18 + 12 * v(r), 18 * std::sin(a));
          const glm::vec3 dir = glm::normalize(glm::vec3(0, 1.5f, 0) - light);
          auto v3 = [](const glm::vec3& x) { return glslFloat(x.x) + " " + glslFloat(x.y) + " " + glslFloat(x.z); };
          return std::vector<std::string>{"--set", "compare=manual",
                                          "--set", "light0.position=" + v3(light),
                                          "--set", "light0.direction=" + v3(dir),
                                          "--set", "camera.yaw=" + glslFloat(6.2832f * v(r)),
                                          "--set", "bias=" + glslFloat(0.002f * v(r))};
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("02_shadow_maps", hidden), true);
}  // namespace

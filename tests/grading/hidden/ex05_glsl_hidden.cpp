// Hidden GLSL cases for lesson 05 (instructor tree only): random searches, and the lesson rendered
// with random cameras, light radii and tap counts, with the seed the grader chooses.
#include <random>

#include "../glsl/ex05_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "random_view.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex05 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex05glsl::randomSearches(rng, "ex05.6: hidden random searches " + std::to_string(i)));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex05.6: hidden render " + std::to_string(i) + ": a random camera, light radius and taps",
        [i](std::mt19937_64& r) {
          std::uniform_real_distribution<float> u(0, 1);
          return std::vector<std::string>{"--set", "technique=pcss",
                                          "--set", "camera.yaw=" + glslFloat(6.2832f * u(r)),
                                          "--set", "light0.radius=" + glslFloat(0.3f + 1.2f * u(r)),
                                          "--set", "pcss.search_taps=" + std::string(i == 0 ? "8" : "32")};
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("05_soft_shadows", hidden), true);
}  // namespace

// Hidden GLSL cases for lesson 05 (instructor tree only): random searches, and the lesson rendered
// with random cameras, light radii and tap counts, with the seed the grader chooses.
#include <random>

#include "../glsl/ex05_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex05 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex05glsl::randomSearches(rng, "ex05.6: hidden random searches " + std::to_string(i)));
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 2; ++i)
    h.renders.push_back({"ex05.6: hidden render " + std::to_string(i) + ": a random camera, light radius and taps",
                         {"--set", "technique=pcss", "--set", "camera.yaw=" + glslFloat(6.2832f * u(rng)), "--set",
                          "light0.radius=" + glslFloat(0.3f + 1.2f * u(rng)), "--set",
                          "pcss.search_taps=" + std::string(i == 0 ? "8" : "32")},
                         8,
                         0.001,
                         0.05,
                         true});
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("05_soft_shadows", hidden), true);
}  // namespace

// Hidden GLSL cases for lesson 09 (instructor tree only): random face choices, and the lesson
// rendered with face maps from random cameras and suns, with the seed the grader chooses.
#include <random>
#include <string>
#include <vector>

#include "../glsl/ex09_glsl_cases.hpp"
#include "random_view.hpp"
#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex09 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex09glsl::randomFaces(rng, "ex09.6: hidden random faces " + std::to_string(i)));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex09.6: hidden render " + std::to_string(i) + ": face maps, a random sun and camera",
        [](std::mt19937_64& r) {
          std::vector<std::string> args{"--set", "fix.faces=always", "--set", "bias=constant"};
          for (std::string& a : shadowlab::glslcases::randomSunAndCamera(r, 0.6f)) args.push_back(std::move(a));
          return args;
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("09_psm_fixes", hidden), true);
}  // namespace

// Hidden GLSL cases for lesson 08 (instructor tree only): random lookups, and the lesson rendered
// from random cameras and suns, with the seed the grader chooses.
#include <random>
#include <string>
#include <vector>

#include "../glsl/ex08_glsl_cases.hpp"
#include "random_view.hpp"
#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex08 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex08glsl::randomLookups(rng, "ex08.3: hidden random lookups " + std::to_string(i)));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex08.3: hidden render " + std::to_string(i) + ": a random sun and camera", [](std::mt19937_64& r) {
          std::vector<std::string> args{"--set", "technique=psm"};
          for (std::string& a : shadowlab::glslcases::randomSunAndCamera(r, 0.6f)) args.push_back(std::move(a));
          return args;
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("08_psm", hidden), true);
}  // namespace

// Hidden GLSL cases for lesson 04 (instructor tree only): random extrusions, and the lesson
// rendered from random cameras and suns with silhouettes=gpu, with the seed the grader chooses.
#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "../glsl/ex04_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "random_view.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex04 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(
        shadowlab::ex04glsl::randomExtrusion(rng, "ex04.5: hidden random extrusions " + std::to_string(i), i % 2 == 1));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex04.5: hidden render " + std::to_string(i) + ": a random sun and camera, silhouettes=gpu",
        [i](std::mt19937_64& r) {
          std::vector<std::string> args{"--set", "silhouettes=gpu", "--set",
                                        std::string("method=") + (i == 0 ? "z_fail" : "auto")};
          for (std::string& a : shadowlab::glslcases::randomSunAndCamera(r, 0.5f)) args.push_back(std::move(a));
          return args;
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("04_shadow_volumes", hidden), true);
}  // namespace

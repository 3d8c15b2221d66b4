// Hidden GLSL cases for lesson 07 (instructor tree only): random descents, and the lesson
// rendered from random cameras and suns, with the seed the grader chooses.
#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "../glsl/ex07_glsl_cases.hpp"
#include "app/glsl_cases.hpp"
#include "random_view.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::glslFloat;

shadowlab::HiddenGlsl hidden() {
  shadowlab::HiddenGlsl h;
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex07 GLSL hidden"));
  for (int i = 0; i < 24; ++i)
    h.cases.push_back(shadowlab::ex07glsl::randomDescent(rng, "ex07.5: hidden random descents " + std::to_string(i)));
  for (int i = 0; i < 2; ++i)
    h.renders.push_back(shadowlab::glslcases::randomRender(
        rng, "ex07.5: hidden render " + std::to_string(i) + ": a random sun and camera", [i](std::mt19937_64& r) {
          std::vector<std::string> args = shadowlab::glslcases::randomSunAndCamera(r, 0.6f);
          const int extra = int(2 * std::uniform_real_distribution<float>(0, 1)(r));
          args.insert(args.end(), {"--set", "levels=" + std::to_string(1 + i + extra)});
          return args;
        }));
  return h;
}

const bool registered = (shadowlab::registerHiddenGlslCases("07_hybrid_maps", hidden), true);
}  // namespace

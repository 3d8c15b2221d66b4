// Public GLSL cases for lesson 03: exercise 03.6 (pcfKernel) in shaders/03_shadow_quality/
// exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp) on two 8x8 depth maps
// the prelude's tap2D compares against; expected values are worked out by hand, or (random cases)
// the reference GLSL's. The renders compare the whole lesson, filter=pcf_nxn, with your shader
// against the reference (tests/grading/glsl_grader.cpp). Every case holds a (partly) shadowed
// answer, so the untouched stub (always lit) fails it.
//
// Tolerance 1e-5: a kernel's value is k / n^2 (k lit taps of n^2), so the smallest wrong answer
// (one tap more or less, n = 7) is 1/49 ~ 0.02 away; the sum of 0/1 taps is exact in float and only
// the division rounds (< 1e-7), so any equivalent way of writing it (sum * (1 / n^2), a running
// mean) passes. The random cases keep every tap robust to rounding: each tap lands at least 0.2
// texel from a texel edge, and each tap's depth 0.005 from every stored depth (stored depths are
// multiples of 0.01, tap depths 0.005 plus multiples of 0.01).
#include <random>

#include "app/glsl_cases.hpp"
#include "ex03_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::GlslCase;

shadowlab::GlslExerciseSet ex03() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"03.6"};
  set.source = "tests/grading/glsl/ex03_glsl.cpp";
  set.prelude = shadowlab::ex03glsl::kPrelude;
  set.fixtures = shadowlab::ex03glsl::fixtures();
  const std::string edge = shadowlab::ex03glsl::kEdgeMap;
  // Texel (3, 3) of map 0 is uv (0.4375, 0.4375): the last shadowing column; (4, 3) is the first lit one.
  set.cases = {
      {"ex03.6: one tap (n = 1) is the plain comparison",
       "vec4(pcfKernel(0, vec2(0.4375), 0.5, vec2(0.0), 0.125, 1), pcfKernel(0, vec2(0.5625, 0.4375), 0.5, vec2(0.0), "
       "0.125, 1), 0, 0)",
       glm::vec4(0, 1, 0, 0), 1e-5f, 2, edge + "; texel (3, 3) then (4, 3) against depth 0.5"},
      {"ex03.6: a 3 x 3 kernel across the edge",
       "vec4(pcfKernel(0, vec2(0.4375), 0.5, vec2(0.0), 0.125, 3), pcfKernel(0, vec2(0.5625, 0.4375), 0.5, vec2(0.0), "
       "0.125, 3), 0, 0)",
       glm::vec4(1.0f / 3, 2.0f / 3, 0, 0), 1e-5f, 2,
       edge + "; around texel (3, 3): columns 2, 3 shadow, 4 lit; around (4, 3): 3 shadows, 4, 5 lit"},
      {"ex03.6: 5 x 5 and 7 x 7 kernels",
       "vec4(pcfKernel(0, vec2(0.4375), 0.5, vec2(0.0), 0.125, 5), pcfKernel(0, vec2(0.4375), 0.5, vec2(0.0), 0.125, "
       "7), 0, 0)",
       glm::vec4(0.4f, 3.0f / 7, 0, 0), 1e-5f, 2, edge + "; around texel (3, 3): columns 4, 5 (and 6) of 5 (of 7) lit"},
      {"ex03.6: the taps follow the receiver plane along u",
       "vec4(pcfKernel(0, vec2(0.4375), 0.3, vec2(1.2, 0.0), 0.125, 3), pcfKernel(0, vec2(0.4375), 0.3, vec2(0.0), "
       "0.125, 3), 0, 0)",
       glm::vec4(2.0f / 3, 1.0f / 3, 0, 0), 1e-5f, 2,
       edge + "; depth 0.3 sloped 1.2 per unit of u: the taps compare 0.15, 0.3, 0.45 in columns 2, 3, 4"},
      {"ex03.6: ... and along v (dzduv.y goes with the v offset)",
       "vec4(pcfKernel(0, vec2(0.4375), 0.3, vec2(0.0, 1.2), 0.125, 3), 0, 0, 0)", glm::vec4(5.0f / 9, 0, 0, 0), 1e-5f,
       1, edge + "; depth 0.3 sloped 1.2 per unit of v: rows 2, 3, 4 compare 0.15, 0.3, 0.45"},
      {"ex03.6: the taps read the map it is given, at offsets of `texel`",
       "vec4(pcfKernel(1, vec2(0.3125), 0.55, vec2(0.0), 0.125, 3), pcfKernel(0, vec2(0.3125), 0.55, vec2(0.0), 0.125, "
       "3), pcfKernel(0, vec2(0.4375), 0.5, vec2(0.0), 0.25, 3), 0)",
       glm::vec4(4.0f / 9, 0, 1.0f / 3, 0), 1e-5f, 3,
       std::string(shadowlab::ex03glsl::kPatternMap) + "; " + edge +
           "; around texel (2, 2) of map 1 four of nine stored depths reach 0.55; texel 0.25: columns 1, 3, 5"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex03 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex03glsl::randomKernels(rng, "ex03.6: random kernels " + std::to_string(i)));
  // The lesson itself, filter=pcf_nxn: your kernel on every 2D map lookup, with its ground-truth figures.
  set.renders = {
      {"ex03.6: the default view, a 3 x 3 kernel (filter=pcf_nxn)", {"--set", "filter=pcf_nxn"}, 8, 0.001, 0.05, true},
      // The receiver plane in place of the slope bias: a kernel that leaves out dzduv brings the
      // acne back (4 % of the pixels; with the slope bias on, 0.005 %: that render could not see it).
      {"ex03.6: the pcf_5x5 preset, the receiver plane in place of the slope bias",
       {"--preset", "pcf_5x5", "--set", "bias.receiver_plane=true", "--set", "bias.slope=0"},
       8,
       0.001,
       0.05,
       true},
      {"ex03.6: a 7 x 7 kernel on a 512 map, view=visibility",
       {"--set", "filter=pcf_nxn", "--set", "pcf.size=7", "--set", "map_size=512", "--set", "view=visibility"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("03_shadow_quality", ex03), true);
}  // namespace

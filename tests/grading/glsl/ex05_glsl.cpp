// Public GLSL cases for lesson 05: exercise 05.6 (blockerSearch) in shaders/05_soft_shadows/
// exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp) over eight search taps
// and two analytic depth maps the prelude defines; expected values are worked out by hand, or
// (random cases) the reference GLSL's. The renders compare the whole lesson, technique=pcss, with
// your shader against the reference (tests/grading/glsl_grader.cpp). Every case finds a blocker
// somewhere, so the untouched stub (none, ever) fails it.
//
// Tolerance 1e-4: the count is a whole number (one tap more or less is 1 off) and the mean of up to
// eight distances between 3 and 10 rounds below 1e-5 whatever the order of the sum; a wrong tap in
// the mean moves it by at least (the smallest gap between two taps' distances) / 8, thousands of
// times more on these maps. No tap of a hand-made case lies within 0.01 of the blocker threshold;
// a random one lands within rounding (1e-5) of it about once in 30000 cases.
#include <random>

#include "app/glsl_cases.hpp"
#include "ex05_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::ex05glsl::kMaps;

shadowlab::GlslExerciseSet ex05() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"05.6"};
  set.source = "tests/grading/glsl/ex05_glsl.cpp";
  set.prelude = shadowlab::ex05glsl::kPrelude;
  const std::string quarter = shadowlab::ex05glsl::turn(1.5707963f);  // a quarter turn: o -> (-o.y, o.x)
  set.cases = {
      {"ex05.6: the taps left of the step are blockers, their mean is 4",
       "vec4(blockerSearch(0, vec2(0.5), 10.0, vec2(0.0), 0.01, 0.1, mat2(1.0)), 0, 0)", glm::vec4(4, 3, 0, 0), 1e-4f,
       2, std::string(kMaps) + "; x offsets 0.1 * (0.9 -0.3 -0.7 0.2 0.4 -0.5 0.1 0.6): three negative"},
      {"ex05.6: a receiver nearer the light than everything finds none; one under it all, every tap",
       "vec4(blockerSearch(0, vec2(0.5), 3.0, vec2(0.0), 0.01, 0.1, mat2(1.0)), blockerSearch(0, vec2(0.2, 0.5), 10.0, "
       "vec2(0.0), 0.01, 0.1, mat2(1.0)))",
       glm::vec4(0, 0, 4, 8), 1e-4f, 4, kMaps},
      {"ex05.6: the taps are turned before they are scaled and added",
       "vec4(blockerSearch(0, vec2(0.5), 10.0, vec2(0.0), 0.01, 0.1, " + quarter + "), 0, 0)", glm::vec4(4, 4, 0, 0),
       1e-4f, 2, std::string(kMaps) + "; a quarter turn: x offsets -0.1 * o.y, four negative"},
      {"ex05.6: the mean of the blockers' own distances",
       "vec4(blockerSearch(1, vec2(0.5), 100.0, vec2(0.0), 0.01, 0.1, " + quarter + "), 0, 0)",
       glm::vec4(6.06f, 8, 0, 0), 1e-4f, 2,
       std::string(kMaps) + "; all eight block: 3 + 4 (0.5 + 0.1 * 0.85 / 8) + 2 (0.5 + 0.1 * 0.7 / 8)"},
      {"ex05.6: each tap compares against the receiver plane there, less the bias",
       "vec4(blockerSearch(1, vec2(0.5), 6.0, vec2(0.0), 0.01, 0.1, mat2(1.0)), blockerSearch(1, vec2(0.5), 6.0, "
       "vec2(4.0, 2.0), 0.01, 0.1, mat2(1.0)))",
       glm::vec4(5.8325f, 4, 0, 0), 1e-4f, 4,
       std::string(kMaps) + "; flat: taps 3, 4, 6, 7 are below 6 - 0.01; the ramp's own plane: none"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex05 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex05glsl::randomSearches(rng, "ex05.6: random searches " + std::to_string(i)));
  // The lesson itself, technique=pcss: your search for every pixel, with its ground-truth figures.
  set.renders = {
      {"ex05.6: the default view (technique=pcss)", {"--set", "technique=pcss"}, 8, 0.001, 0.05, true},
      {"ex05.6: the contact_hardening preset", {"--preset", "contact_hardening"}, 8, 0.001, 0.05, true},
      {"ex05.6: 32 search taps, view=visibility",
       {"--set", "technique=pcss", "--set", "pcss.search_taps=32", "--set", "view=visibility"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("05_soft_shadows", ex05), true);
}  // namespace

// Public GLSL cases for lesson 10: exercise 10.4 (cascadeAt) in shaders/10_showdown/exercises.glsl.
// Each case evaluates GLSL on the GPU (app/glsl_cases.hpp) through the prelude's cascadeCase, which
// sets shadow_cascades.frag's uniforms; expected values are worked out by hand from the splits
// 1 | 2 | 4 | 8 | 16 and the band, or (random cases) shadow::cascadeAt's. Every case holds a depth some
// cascade covers, so the untouched stub (-1: no cascade, everything lit) fails it.
//
// Tolerance 1e-5 per component: the cascade index is exact (a wrong one is off by 1 or more); the
// weight (depth - start) / width rounds in float by a few ulps of the depth over the band's width,
// below 4e-6 with the random cases' band >= 0.2 and cascades whose end over depth range is <= 5.
#include <random>

#include "app/glsl_cases.hpp"
#include "ex10_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {

// cascadeCase on light 0 with the splits 1 | 2 | 4 | 8 | 16 (count of them) and the band.
std::string octaves(float band, float depth, int count = 4, int light = 0) {
  return "cascadeCase(" + std::to_string(light) + ", " + std::to_string(count) + ", 1.0, vec4(2.0, 4.0, 8.0, 16.0), " +
         shadowlab::glslFloat(band) + ", " + shadowlab::glslFloat(depth) + ")";
}

shadowlab::GlslExerciseSet ex10() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"10.4"};
  set.source = "tests/grading/glsl/ex10_glsl.cpp";
  set.prelude = shadowlab::ex10glsl::kPrelude;
  const std::string note = "splits 1 | 2 | 4 | 8 | 16, band 0.25; x y: (k, weight)";
  set.cases = {
      {"ex10.4: before the band: cascade 0, no weight",
       "vec4(" + octaves(0.25f, 1.5f) + ".xy, " + octaves(0.25f, 3.5f) + ".xy)", glm::vec4(0, 0, 1, 0), 1e-5f, 4,
       note + " at 1.5, z w at 3.5 (the band of [2, 4] starts at 3.5)"},
      {"ex10.4: in the band the weight grows linearly",
       "vec4(" + octaves(0.25f, 1.875f) + ".xy, " + octaves(0.25f, 7.5f) + ".xy)", glm::vec4(0, 0.5f, 2, 0.5f), 1e-5f,
       4, note + " at 1.875, z w at 7.5"},
      {"ex10.4: on a split: the nearer cascade, the next one's weight 1", octaves(0.25f, 2.0f), glm::vec4(0, 1, 0, 0),
       1e-5f, 2, note + " at 2.0"},
      {"ex10.4: the last cascade has no next, beyond the ends none",
       "vec4(" + octaves(0.25f, 15.9f) + ".x, " + octaves(0.25f, 16.5f) + ".x, " + octaves(0.25f, 0.5f) + ".x, " +
           octaves(0.25f, 16.0f) + ".y)",
       glm::vec4(3, -1, -1, 0), 1e-5f, 4, "splits 1 | 2 | 4 | 8 | 16, band 0.25: k at 15.9, 16.5, 0.5; weight at 16"},
      {"ex10.4: band 0: no weight, band 1: the whole cascade blends",
       "vec4(" + octaves(0.0f, 1.99f) + ".xy, " + octaves(1.0f, 1.5f) + ".xy)", glm::vec4(0, 0, 0, 0.5f), 1e-5f, 4,
       "splits 1 | 2 | 4 | 8 | 16: x y band 0 at 1.99, z w band 1 at 1.5"},
      {"ex10.4: only the light's count of cascades counts",
       "vec4(" + octaves(0.25f, 3.9f, 2) + ".xy, " + octaves(0.25f, 6.0f, 2) + ".x, 0.0)", glm::vec4(1, 0, -1, 0),
       1e-5f, 3, "2 cascades 1 | 2 | 4 (uCsmFar's z w unused), band 0.25: x y at 3.9 (the last), z at 6"},
      {"ex10.4: the light's own cascades", octaves(0.25f, 3.75f, 4, 1), glm::vec4(1, 0.5f, 0, 0), 1e-5f, 2,
       "light 1: splits 1 | 2 | 4 | 8 | 16, band 0.25, at 3.75; light 0 holds other cascades"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex10 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex10glsl::randomChoices(rng, "ex10.4: random choices " + std::to_string(i)));
  // The lesson itself, technique=csm: your choice for every pixel, with its ground-truth figures.
  set.renders = {
      {"ex10.4: the default view (technique=csm)", {"--set", "technique=csm"}, 8, 0.001, 0.05, true},
      {"ex10.4: the widest blend band", {"--set", "technique=csm", "--set", "csm.band=0.5"}, 8, 0.001, 0.05, true},
      {"ex10.4: two cascades", {"--set", "technique=csm", "--set", "csm.cascades=2"}, 8, 0.001, 0.05, true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("10_showdown", ex10), true);
}  // namespace

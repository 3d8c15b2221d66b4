// Public GLSL cases for lesson 02: exercises 02.4 (shadowCompare) and 02.5 (shadowLookup) in
// shaders/02_shadow_maps/exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp);
// expected values are worked out by hand, or (random cases) the reference GLSL's. The renders
// compare the whole lesson with your shader against the reference (tests/grading/glsl_grader.cpp).
// Every case holds at least one shadowed answer, so an untouched stub (always lit) fails it.
#include <random>

#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::GlslCase;
using shadowlab::glslFloat;
using shadowlab::glslVec;

// shadowCompare(d, s, b) four times: a random pair each, then one certainly shadowed, one lit.
GlslCase randomCompare(std::mt19937_64& rng, int i) {
  std::uniform_real_distribution<float> u(0, 1);
  std::string e = "vec4(";
  for (int k = 0; k < 4; ++k) {
    const float s = u(rng), b = 0.02f * u(rng);
    const float d = k == 2 ? s + b + 0.01f + 0.2f * u(rng) : k == 3 ? s + b - 0.01f - 0.2f * u(rng) : u(rng);
    e += (k ? ", " : "") + std::string("shadowCompare(") + glslFloat(d) + ", " + glslFloat(s) + ", " + glslFloat(b) +
         ")";
  }
  return {"ex02.4: random depths and biases " + std::to_string(i) + " (seed " +
              std::to_string(shadowlab::grading::seed()) + ")",
          e + ")",
          std::nullopt,
          0,
          4,
          "each component: shadowCompare(depth, stored, bias)"};
}

// shadowLookup on the 4x2 map: three random coordinates (homogeneous, some outside), then texel
// (0, 0) whose 0.2 shadows depth 0.5.
GlslCase randomLookup(std::mt19937_64& rng, int i) {
  std::uniform_real_distribution<float> u(0, 1);
  std::string e = "vec4(";
  for (int k = 0; k < 3; ++k) {
    const float w = 0.5f + 1.5f * u(rng);
    const glm::vec4 c(w * (1.2f * u(rng) - 0.1f), w * (1.2f * u(rng) - 0.1f), w * 1.1f * u(rng), w);
    e += "shadowLookup(uCaseMap, " + glslVec(c) + ", 0.01), ";
  }
  const float w = 0.5f + 1.5f * u(rng);
  e += "shadowLookup(uCaseMap, " + glslVec(glm::vec4(0.125f, 0.25f, 0.5f, 1.0f) * w) + ", 0.01))";
  return {"ex02.5: random lookups " + std::to_string(i) + " (seed " + std::to_string(shadowlab::grading::seed()) + ")",
          e,
          std::nullopt,
          0,
          4,
          "uCaseMap: 4x2, row 0 (v < 0.5) 0.2 0.8 0.8 0.8, row 1 0.8 0.8 0.3 0.8"};
}

shadowlab::GlslExerciseSet ex02() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"02.4", "02.5"};
  set.source = "tests/grading/glsl/ex02_glsl.cpp";
  set.prelude = "uniform sampler2D uCaseMap;  // 4x2: row 0 (v < 0.5) 0.2 0.8 0.8 0.8, row 1 0.8 0.8 0.3 0.8\n";
  set.fixtures = {{"uCaseMap", 4, 2, {0.2f, 0.8f, 0.8f, 0.8f, 0.8f, 0.8f, 0.3f, 0.8f}}};
  const std::string map = "uCaseMap: 4x2, row 0 (v < 0.5) 0.2 0.8 0.8 0.8, row 1 0.8 0.8 0.3 0.8";
  set.cases = {
      {"ex02.4: in front of what the light saw: lit; behind it: shadowed",
       "vec4(shadowCompare(0.4, 0.6, 0.0), shadowCompare(0.6, 0.4, 0.0), 0, 0)", glm::vec4(1, 0, 0, 0), 0, 2},
      {"ex02.4: equal depths are lit (LEQUAL), a little behind is not",
       "vec4(shadowCompare(0.5, 0.5, 0.0), shadowCompare(0.501, 0.5, 0.0), 0, 0)", glm::vec4(1, 0, 0, 0), 0, 2},
      {"ex02.4: the bias removes acne, a real occluder still shadows",
       "vec4(shadowCompare(0.505, 0.5, 0.01), shadowCompare(0.52, 0.5, 0.01), 0, 0)", glm::vec4(1, 0, 0, 0), 0, 2},
      {"ex02.5: each texel of a 4x2 map",
       "vec4(shadowLookup(uCaseMap, vec4(0.1, 0.2, 0.5, 1.0), 0.0), shadowLookup(uCaseMap, vec4(0.3, 0.2, 0.5, 1.0), "
       "0.0), shadowLookup(uCaseMap, vec4(0.6, 0.7, 0.5, 1.0), 0.0), shadowLookup(uCaseMap, vec4(0.6, 0.2, 0.5, "
       "1.0), 0.0))",
       glm::vec4(0, 1, 0, 1), 0, 4, map + "; texels (0,0) 0.2, (1,0) 0.8, (2,1) 0.3, (2,0) 0.8 against depth 0.5"},
      {"ex02.5: rows and columns not swapped",
       "vec4(shadowLookup(uCaseMap, vec4(0.1, 0.7, 0.5, 1.0), 0.0), shadowLookup(uCaseMap, vec4(0.6, 0.7, 0.5, 1.0), "
       "0.0), 0, 0)",
       glm::vec4(1, 0, 0, 0), 0, 2, map + "; texel (0,1) is 0.8, texel (2,1) is 0.3"},
      {"ex02.5: divides by w first",
       "vec4(shadowLookup(uCaseMap, vec4(0.2, 0.4, 1.0, 2.0), 0.0), shadowLookup(uCaseMap, vec4(0.9, 0.6, 1.5, 3.0), "
       "0.0), 0, 0)",
       glm::vec4(0, 1, 0, 0), 0, 2, map + "; (0.2, 0.4, 1, 2) is (0.1, 0.2, 0.5): texel (0,0)"},
      {"ex02.5: lit outside the map, beyond the far plane and behind the light; shadowed inside",
       "vec4(shadowLookup(uCaseMap, vec4(0.1, 0.2, 0.5, 1.0), 0.0), shadowLookup(uCaseMap, vec4(-0.1, 0.2, 0.5, 1.0), "
       "0.0), shadowLookup(uCaseMap, vec4(0.1, 0.2, 1.5, 1.0), 0.0), shadowLookup(uCaseMap, vec4(-0.1, -0.2, -0.5, "
       "-1.0), 0.0))",
       glm::vec4(0, 1, 1, 1), 0, 4, map},
      {"ex02.5: the bias applies",
       "vec4(shadowLookup(uCaseMap, vec4(0.1, 0.2, 0.21, 1.0), 0.02), shadowLookup(uCaseMap, vec4(0.1, 0.2, 0.21, "
       "1.0), 0.0), 0, 0)",
       glm::vec4(1, 0, 0, 0), 0, 2, map + "; texel (0,0) is 0.2 against depth 0.21"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex02 GLSL"));
  for (int i = 0; i < 8; ++i) set.cases.push_back(randomCompare(rng, i));
  for (int i = 0; i < 8; ++i) set.cases.push_back(randomLookup(rng, i));
  // The lesson itself, compare=manual: your lookup for every pixel, with its ground-truth figures.
  set.renders = {
      {"ex02.5: the lesson's default view (compare=manual)", {"--set", "compare=manual"}, 8, 0.001, 0.05, true},
      {"ex02.5: the acne preset (no polygon offset) (compare=manual)",
       {"--preset", "acne", "--set", "compare=manual"},
       8,
       0.001,
       0.05,
       true},
      {"ex02.5: view=visibility, a 256 map (compare=manual)",
       {"--set", "compare=manual", "--set", "view=visibility", "--set", "map_size=256"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("02_shadow_maps", ex02), true);
}  // namespace

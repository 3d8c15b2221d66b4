// Public GLSL cases for lesson 07: exercise 07.5 (hybridDescend) in shaders/07_hybrid_maps/
// exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp) on two small hybrid
// maps (R32UI roots and an RGBA32UI records texture, the technique's formats); expected values are
// worked out by hand, or (random cases) the reference GLSL's. The renders compare the whole lesson
// with your descent in its visibility against the reference (tests/grading/glsl_grader.cpp). Every
// stored depth is below 1, so the untouched stub (depth 1.0 at the root) fails every case.
//
// Tolerance 0: a descent copies a stored word's bits (the depth) and counts whole levels and steps,
// so any correct walk returns exactly the reference's values; one wrong child or level lands on
// another leaf (all leaves of a record differ) or another count.
#include <random>

#include "app/glsl_cases.hpp"
#include "ex07_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::ex07glsl::kMaps;

shadowlab::GlslExerciseSet ex07() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"07.5"};
  set.source = "tests/grading/glsl/ex07_glsl.cpp";
  set.prelude = shadowlab::ex07glsl::kPrelude;
  set.fixtures = shadowlab::ex07glsl::fixtures();
  const std::string maps = kMaps;
  set.cases = {
      {"ex07.5: a root word that is a leaf: stored at the root's level, no pointer followed", "descentA(ivec2(1, 2))",
       glm::vec4(0.25f, 2, 0, 0), 0.0f, 3, maps + "; map A, source texel (1, 2): root (0, 0), a leaf storing 0.25"},
      {"ex07.5: one pointer: the child under s one level down", "descentA(ivec2(4, 2))", glm::vec4(0.75f, 1, 1, 0),
       0.0f, 3,
       maps + "; map A, (4, 2): root (1, 0) -> record 0 = [0.5, -> 1, 0.75, 0.125], child ((4 >> 1) & 1, (2 >> 1) & 1) "
              "= (0, 1): 2"},
      {"ex07.5: two pointers down to full resolution", "descentA(ivec2(7, 1))", glm::vec4(0.4f, 0, 2, 0), 0.0f, 3,
       maps + "; map A, (7, 1): record 0 child (1, 0) -> record 1 = [0.1, 0.2, 0.3, 0.4], child (7 & 1, 1 & 1) = (1, "
              "1): 3"},
      {"ex07.5: x picks the child's column, y its row", "descentA(ivec2(6, 1))", glm::vec4(0.3f, 0, 2, 0), 0.0f, 3,
       maps + "; map A, (6, 1): record 1 = [0.1, 0.2, 0.3, 0.4], child (0, 1): 2 (not 1)"},
      {"ex07.5: a record on the records' second row (r >> 10)", "descentA(ivec2(0, 4))", glm::vec4(0.6f, 1, 1, 0), 0.0f,
       3, maps + "; map A, (0, 4): root (0, 1) -> record 1025 (texel (1, 1)) = [0.6, 0.65, 0.7, -> 3], child 0"},
      {"ex07.5: ... and down from it", "descentA(ivec2(2, 6))", glm::vec4(0.9f, 0, 2, 0), 0.0f, 3,
       maps + "; map A, (2, 6): record 1025 child (1, 1) -> record 3 = [0.9, 0.8, 0.7, 0.05], child (0, 0)"},
      {"ex07.5: three levels: three pointers from the root to full resolution", "descentB(ivec2(2, 1))",
       glm::vec4(0.63f, 0, 3, 0), 0.0f, 3,
       maps + "; map B, (2, 1): root -> record 4 = [-> 5, 0.33, 0.44, 0.55], child 0 -> 5 = [0.15, -> 6, 0.35, 0.45], "
              "child 1 -> 6 = [0.61, 0.62, 0.63, 0.64], child (0, 1): 2"},
      {"ex07.5: three levels, a leaf one level below the root", "descentB(ivec2(5, 0))", glm::vec4(0.33f, 2, 1, 0),
       0.0f, 3, maps + "; map B, (5, 0): root -> record 4 = [-> 5, 0.33, 0.44, 0.55], child ((5 >> 2) & 1, 0) = 1"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex07 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex07glsl::randomDescent(rng, "ex07.5: random descents " + std::to_string(i)));
  // The lesson itself: your descent for every tap of the sun's hybrid map, with its ground-truth figures.
  set.renders = {
      {"ex07.5: the default view (2 levels, nearest)", {}, 8, 0.001, 0.05, true},
      {"ex07.5: three levels", {"--preset", "levels_3"}, 8, 0.001, 0.05, true},
      {"ex07.5: N x N PCF, each tap descends", {"--preset", "pcf"}, 8, 0.001, 0.05, true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("07_hybrid_maps", ex07), true);
}  // namespace

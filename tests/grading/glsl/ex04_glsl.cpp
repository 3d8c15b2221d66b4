// Public GLSL cases for lesson 04: exercise 04.5 (extrudeToInfinity) in shaders/04_shadow_volumes/
// exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp); expected values are
// worked out by hand, or (random cases) the reference GLSL's. The renders compare the whole lesson,
// silhouettes=gpu, with your geometry shader's extrusion against the reference's
// (tests/grading/glsl_grader.cpp). The untouched stub returns a finite point (w = 1) and fails
// every case.
//
// A case compares vec4(normalize(xyz), w) of your answer: a point at infinity is a direction, and
// any positive multiple of (p - L, 0) projects to the same pixel, so the length is free.
// Tolerance 1e-5 on those unit components: the reference's are exact to float rounding (< 1e-6
// after normalize), and so is any other correct scaling; a wrong answer is off by far more (w by
// 1 for a finite point; a direction toward the light, or a directional light's volume taken as
// p + direction, by at least 0.1 here: every vertex lies 1 m or more from a point light).
#include <cmath>
#include <random>

#include "app/glsl_cases.hpp"
#include "ex04_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::ex04glsl::kNote;

shadowlab::GlslExerciseSet ex04() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"04.5"};
  set.source = "tests/grading/glsl/ex04_glsl.cpp";
  set.prelude = shadowlab::ex04glsl::kPrelude;
  const float s5 = 1.0f / std::sqrt(5.0f);
  set.cases = {
      {"ex04.5: a point light's volume goes on along the ray from the light through the vertex",
       "caseDirection(extrudeToInfinity(vec3(1.0, 2.0, 0.0), vec4(0.0, 4.0, 0.0, 1.0)))", glm::vec4(s5, -2 * s5, 0, 0),
       1e-5f, 4, std::string(kNote) + "; light at (0, 4, 0), p = (1, 2, 0): p - L = (1, -2, 0)"},
      {"ex04.5: a vertex straight below a point light goes straight down",
       "caseDirection(extrudeToInfinity(vec3(2.0, 1.0, -1.0), vec4(2.0, 5.0, -1.0, 1.0)))", glm::vec4(0, -1, 0, 0),
       1e-5f, 4, std::string(kNote) + "; light at (2, 5, -1), p = (2, 1, -1)"},
      {"ex04.5: a point light at the origin: its volume runs radially outward",
       "caseDirection(extrudeToInfinity(vec3(3.0, 0.0, 4.0), vec4(0.0, 0.0, 0.0, 1.0)))", glm::vec4(0.6f, 0, 0.8f, 0),
       1e-5f, 4, std::string(kNote) + "; light at the origin, p = (3, 0, 4)"},
      {"ex04.5: a directional light (the sun straight down): every vertex goes down",
       "caseDirection(extrudeToInfinity(vec3(3.0, 0.5, -2.0), vec4(0.0, 1.0, 0.0, 0.0)))", glm::vec4(0, -1, 0, 0),
       1e-5f, 4, std::string(kNote) + "; direction (0, -1, 0), so light = (0, 1, 0, 0); p = (3, 0.5, -2)"},
      {"ex04.5: a slanted sun: the light's direction, whatever the vertex",
       "caseDirection(extrudeToInfinity(vec3(5.0, 0.0, 5.0), vec4(-1.0 / 3.0, 2.0 / 3.0, -2.0 / 3.0, 0.0)))",
       glm::vec4(1.0f / 3, -2.0f / 3, 2.0f / 3, 0), 1e-5f, 4,
       std::string(kNote) + "; direction (1, -2, 2) / 3, p = (5, 0, 5): not p + direction"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex04 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(
        shadowlab::ex04glsl::randomExtrusion(rng, "ex04.5: random extrusions " + std::to_string(i), i % 2 == 1));
  // The lesson itself, silhouettes=gpu: your extrusion for every volume vertex at infinity, with
  // its ground-truth figures (z-pass and z-fail, the sun and point lights).
  set.renders = {
      {"ex04.5: the default view, silhouettes=gpu", {"--set", "silhouettes=gpu"}, 8, 0.001, 0.05, true},
      {"ex04.5: the camera inside a volume, z-fail (far caps at infinity)",
       {"--preset", "camera_in_volume_zfail", "--set", "silhouettes=gpu"},
       8,
       0.001,
       0.05,
       true},
      {"ex04.5: four lights, point and spot, silhouettes=gpu",
       {"--preset", "many_lights", "--set", "silhouettes=gpu"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("04_shadow_volumes", ex04), true);
}  // namespace

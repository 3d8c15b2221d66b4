// Public GLSL cases for lesson 08: exercise 08.3 (psmMapCoords) in shaders/08_psm/exercises.glsl.
// Each case evaluates GLSL on the GPU (app/glsl_cases.hpp); expected values are worked out by hand,
// or (random cases) the reference GLSL's. The renders compare the whole lesson, technique=psm,
// with your shader against the reference (tests/grading/glsl_grader.cpp). Every case holds a point
// the map knows, so the untouched stub (vec4(0.0): nothing known, everything lit) fails it.
//
// Tolerance 1e-4: the product M (p, 1) is the same GLSL in any answer; only the divide and the
// scale to [0, 1] round, a few ulps of values below 2.5 (< 1e-6) however they are written
// (h.xyz / h.w * 0.5 + 0.5, (h.xyz + h.w) / (2 h.w), ...). A wrong step is off by far more: the
// hand-made cases catch a missed divide, scale or w test by a tenth or more; the random cases keep
// |w| in [0.5, 0.75] or [1.25, 2] (not dividing moves each coordinate by at least a tenth of its
// h), the divided coordinates within 4, and every point at least 0.5 from w = 0.
#include <random>

#include "app/glsl_cases.hpp"
#include "ex08_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {

shadowlab::GlslExerciseSet ex08() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"08.3"};
  set.source = "tests/grading/glsl/ex08_glsl.cpp";
  // A camera-like projection: h = (x, y, z, -z) (in front: z < 0), and its negation, as the inverse
  // projection of lesson 09 flips w: h = (-x, -y, -z, z).
  const std::string persp = "mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 0, 0)";
  const std::string flipped = "mat4(-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 1, 0, 0, 0, 0)";
  set.cases = {
      {"ex08.3: the identity: window coordinates are clip * 0.5 + 0.5", "psmMapCoords(mat4(1.0), vec3(0.2, -0.4, 0.6))",
       glm::vec4(0.6f, 0.3f, 0.8f, 1), 1e-4f, 4, "worldToClip = identity, worldPos (0.2, -0.4, 0.6)"},
      {"ex08.3: the point is (worldPos, 1): the matrix's translation counts",
       "psmMapCoords(mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.2, -0.4, 0.1, 1), vec3(0.0))",
       glm::vec4(0.6f, 0.3f, 0.55f, 1), 1e-4f, 4, "worldToClip translates by (0.2, -0.4, 0.1); worldPos 0"},
      {"ex08.3: divides by w", "psmMapCoords(" + persp + ", vec3(0.5, -1.0, -2.0))", glm::vec4(0.625f, 0.25f, 0.0f, 1),
       1e-4f, 4, "h = (x, y, z, -z) = (0.5, -1, -2, 2)"},
      {"ex08.3: a homogeneous scale changes nothing, and a depth beyond the far plane comes back as it is",
       "psmMapCoords(mat4(2.0), vec3(0.0, 0.0, 1.5))", glm::vec4(0.5f, 0.5f, 1.25f, 1), 1e-4f, 4,
       "worldToClip = 2 I: h = (0, 0, 3, 2); the caller, not the lookup, treats depth > 1 as lit"},
      {"ex08.3: w < 0 and w = 0 are outside every light frustum",
       "vec4(psmMapCoords(" + persp + ", vec3(0.5, -1.0, 2.0)).w, psmMapCoords(" + persp +
           ", vec3(0.5, -1.0, 0.0)).w, psmMapCoords(" + persp + ", vec3(0.5, -1.0, -2.0)).w, psmMapCoords(" + persp +
           ", vec3(0.5, -1.0, 2.0)).x)",
       glm::vec4(0, 0, 1, 0), 1e-4f, 4,
       "h = (x, y, z, -z): z = 2 gives w = -2, z = 0 gives w = 0 (both vec4(0.0)), z = -2 gives w = 2"},
      {"ex08.3: the sign of w decides, not the side of the eye", "psmMapCoords(" + flipped + ", vec3(0.5, -1.0, 2.0))",
       glm::vec4(0.375f, 0.75f, 0.0f, 1), 1e-4f, 4,
       "h = (-x, -y, -z, z) = (-0.5, 1, -2, 2): a point behind the camera that this map knows"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex08 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex08glsl::randomLookups(rng, "ex08.3: random lookups " + std::to_string(i)));
  // The lesson itself, technique=psm: your lookup for every pixel, with its ground-truth figures.
  set.renders = {
      {"ex08.3: the default view (technique=psm)", {"--set", "technique=psm"}, 8, 0.001, 0.05, true},
      {"ex08.3: the behind preset (the virtual camera's slide)", {"--preset", "behind"}, 8, 0.001, 0.05, true},
      {"ex08.3: the facing preset, view=visibility",
       {"--preset", "facing", "--set", "view=visibility"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("08_psm", ex08), true);
}  // namespace

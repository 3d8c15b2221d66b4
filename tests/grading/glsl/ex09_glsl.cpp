// Public GLSL cases for lesson 09: exercise 09.6 (cubeFaceLayer) in shaders/09_psm_fixes/
// exercises.glsl. Each case evaluates GLSL on the GPU (app/glsl_cases.hpp); expected values are
// worked out by hand, or (random cases) the reference GLSL's. The renders compare the whole lesson
// with face maps (fix 3) drawn with your shader against the reference
// (tests/grading/glsl_grader.cpp). Every case holds a point on some face's map, so the untouched
// stub (-1: no face, lit) fails it.
//
// Tolerance 0: the answer is a layer index, exact in float. The random calls keep away from the
// cases where rounding could pick either of two faces (ex09_glsl_cases.hpp): moving the point or
// the light by 1e-3 along any axis leaves the answer as it is, and the point is at least 0.2 from
// a point light.
#include <random>

#include "app/glsl_cases.hpp"
#include "ex09_glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {

shadowlab::GlslExerciseSet ex09() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"09.6"};
  set.source = "tests/grading/glsl/ex09_glsl.cpp";
  const std::string all = "int[6](0, 1, 2, 3, 4, 5)";     // every face has a map, layer = face
  const std::string beyond = "vec4(0.0, 0.0, 3.0, 1.0)";  // a point light beyond the far face
  set.cases = {
      {"ex09.6: a direction: the ray through the point runs along -direction",
       "vec4(cubeFaceLayer(vec3(0.3, 0.2, -0.1), vec4(0, 1, 0, 0), " + all +
           "), cubeFaceLayer(vec3(0.3, 0.2, -0.1), vec4(1, 0, 0, 0), " + all + "), 0, 0)",
       glm::vec4(3, 1, 0, 0), 0, 2, "light (0, 1, 0, 0): the ray goes -y (face 3); (1, 0, 0, 0): -x (face 1)"},
      {"ex09.6: a point light beyond the far face: the face the ray leaves by, not the one it enters by",
       "vec4(cubeFaceLayer(vec3(0.2, 0.0, 0.5), " + beyond + ", " + all + "), cubeFaceLayer(vec3(0.9, 0.0, 0.5), " +
           beyond + ", " + all + "), 0, 0)",
       glm::vec4(5, 0, 0, 0), 0, 2,
       "light at (0, 0, 3): v = (0.2, 0, -2.5) leaves by -z at t = 1.6 (+x: t = 5; it entered by +z at t = "
       "0.8); v = (0.9, 0, -2.5) leaves by +x at t = 1.11"},
      {"ex09.6: faces without a map are skipped, and the answer is the face's layer",
       "vec4(cubeFaceLayer(vec3(0.2, 0.0, 0.5), " + beyond +
           ", int[6](2, -1, 0, 1, -1, -1)), cubeFaceLayer(vec3(-0.3, "
           "-0.2, 0.5), " +
           beyond + ", int[6](2, -1, 0, 1, -1, -1)), 0, 0)",
       glm::vec4(2, 1, 0, 0), 0, 2,
       "layers +x 2, +y 0, -y 1, no map on -x, +z, -z: v = (0.2, 0, -2.5) then +x (t = 5); v = (-0.3, -0.2, -2.5) "
       "then -y (t = 5; -x at 3.3 has none)"},
      {"ex09.6: a point light inside the cube: the nearest face the ray crosses outward",
       "vec4(cubeFaceLayer(vec3(0.5, 0.2, -0.1), vec4(0, 0, 0, 1), " + all +
           "), cubeFaceLayer(vec3(-0.1, -0.6, 0.3), vec4(0, 0, 0, 1), " + all + "), 0, 0)",
       glm::vec4(0, 3, 0, 0), 0, 2, "light at the centre: v = q, +x at t = 2 then -y at t = 1.67"},
      {"ex09.6: a slanted direction",
       "vec4(cubeFaceLayer(vec3(0.5, 0.5, 0.0), vec4(1, 2, 0.5, 0), " + all +
           "), cubeFaceLayer(vec3(-0.8, 0.9, 0.0), vec4(1, 2, 0.5, 0), " + all + "), 0, 0)",
       glm::vec4(3, 1, 0, 0), 0, 2,
       "v = (-1, -2, -0.5) from q: (0.5, 0.5, 0) -x at 1.5, -y at 0.75, -z at 2; (-0.8, 0.9, 0) -x at 0.2, -y at "
       "0.95"},
      {"ex09.6: no face: the light's own point, or no mapped face the ray crosses outward",
       "vec4(cubeFaceLayer(vec3(0.0), vec4(0, 0, 0, 1), " + all +
           "), cubeFaceLayer(vec3(0.3, 0.2, -0.1), vec4(0, 1, 0, 0), int[6](0, 1, 2, -1, 4, 5)), "
           "cubeFaceLayer(vec3(0.3, 0.2, -0.1), vec4(0, 1, 0, 0), " +
           all + "), 0)",
       glm::vec4(-1, -1, 3, 0), 0, 3, "v = 0 at the light; v = (0, -1, 0) with no map on -y; the same with one"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex09 GLSL"));
  for (int i = 0; i < 8; ++i)
    set.cases.push_back(shadowlab::ex09glsl::randomFaces(rng, "ex09.6: random faces " + std::to_string(i)));
  // The lesson itself with face maps: your choice of map for every pixel, with its ground-truth
  // figures. bias=constant: with the world bias impl=student also moves the caster vertices on the
  // CPU by exercise 09.4 (in double; the reference does it in float in depth_psm.vert), which alone
  // moves up to 1 % of the pixels; with the constant bias only your shader differs.
  set.renders = {
      {"ex09.6: the faces_always preset", {"--preset", "faces_always", "--set", "bias=constant"}, 8, 0.001, 0.05, true},
      {"ex09.6: the faces_auto preset (the sun along the view, five faces)",
       {"--preset", "faces_auto", "--set", "bias=constant"},
       8,
       0.001,
       0.05,
       true},
      {"ex09.6: the faces_point_inside preset (all six faces), view=visibility",
       {"--preset", "faces_point_inside", "--set", "bias=constant", "--set", "view=visibility"},
       8,
       0.001,
       0.05,
       true},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("09_psm_fixes", ex09), true);
}  // namespace

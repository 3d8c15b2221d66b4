#pragma once
// GLSL exercise cases: the GLSL twin of the doctest graders. A case is a GLSL expression over the
// exercise's functions (of type vec4), evaluated on the GPU, one pixel per case, by a fragment
// shader that includes the lesson's exercises.glsl (the student's) or exercises_reference.glsl; it
// passes when the student's value is within the tolerance of the expected one: a literal, or the
// reference GLSL's own value on the same inputs. A student file that does not compile fails every
// case with the compiler's error (file:line). The lesson's exercises panel runs the public cases
// in-process (app/exercises.hpp); tests/grading/glsl_grader.cpp adds the hidden cases and renders
// of the whole lesson (student's shader against the reference) to grade.
//
// Cases are registered by tests/grading/glsl/exNN_glsl.cpp (public) and
// tests/grading/hidden/exNN_glsl_hidden.cpp (hidden, made when the grader runs: they use its seed).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "grading/cases.hpp"

namespace shadowlab {

struct GlslCase {
  std::string name;                   // "ex02.4: equal depths: LEQUAL says lit" (exercise from the prefix)
  std::string expression;             // GLSL of type vec4, e.g. "vec4(shadowCompare(0.5, 0.5, 0.0))"
  std::optional<glm::vec4> expected;  // none: the reference GLSL's value for the same expression
  float tolerance = 0;                // absolute, per component
  int components = 1;                 // how many of the 4 are meaningful (the rest are not compared)
  std::string note;                   // what the inputs mean, printed with a failure
  bool hidden = false;
};

// An R32F texture the cases read through `sampler` (declared by the prelude as sampler2D):
// GL_NEAREST, clamped to the edge, row 0 at v = 0. With `words` instead of `values`, an integer
// texture (a usampler2D): R32UI, or RGBA32UI with channels = 4 (four words a texel).
struct GlslFixture {
  std::string sampler;
  int width = 0, height = 0;
  std::vector<float> values;
  std::vector<std::uint32_t> words;
  int channels = 1;
};

// A render of the whole lesson, headless, with the student's shader (impl=student) and with the
// reference (impl=reference), everything else equal: graded by tests/grading/glsl_grader.cpp, not
// by the panel. It passes when at most maxDifferingShare of the pixels differ by more than
// channelTolerance (0-255) in some channel and, for a measurable lesson, each ground-truth figure
// of --measure (misclassified, leak and false-shadow percentages) is within figureTolerance
// percentage points of the reference's.
struct GlslRender {
  std::string name;               // "ex02.5: the lesson's default view, compare=manual"
  std::vector<std::string> args;  // the lesson's command line beyond --headless/--size/--screenshot
  int channelTolerance = 8;
  double maxDifferingShare = 0.001;
  double figureTolerance = 0.05;
  bool measure = false;
  bool hidden = false;
  // A random placement (hidden renders): the arguments drawn again for attempt 1, 2, ... The
  // grader redraws while the reference's render of the last arguments shows too little to grade
  // (a camera facing a wall, no shadow in view) or the untouched stub's render matches it (the
  // lesson never ran the exercise's code in view, e.g. lesson 09 falling back to its uniform map
  // where face maps were asked for): a draw like that would let an untouched stub pass. Empty: a
  // fixed view, graded as it is.
  std::function<std::vector<std::string>(int attempt)> redraw;
};

struct GlslExerciseSet {
  std::string lesson;            // "02_shadow_maps": shaders/<lesson>/exercises.glsl
  std::vector<std::string> ids;  // the GLSL exercises, "02.4", "02.5"
  std::string prelude;           // GLSL before the exercise file: what it may call, fixtures' samplers
  std::vector<GlslFixture> fixtures;
  std::vector<GlslCase> cases;
  std::vector<GlslRender> renders;
  std::string source;  // repository-relative file that registered the public cases
};

// The makers run when the set is asked for, so randomised cases take the grader's seed.
void registerGlslExercises(const std::string& lesson, std::function<GlslExerciseSet()> make);
struct HiddenGlsl {
  std::vector<GlslCase> cases;
  std::vector<GlslRender> renders;
};
void registerHiddenGlslCases(const std::string& lesson, std::function<HiddenGlsl()> make);
// The lesson's set (public cases; with the hidden ones appended when asked), if it has one.
std::optional<GlslExerciseSet> glslExercises(const std::string& lesson, bool withHidden);

// GLSL literals for generated expressions: "0.25", "vec2(0.5, 1.0)", exact to float precision.
std::string glslFloat(float v);
std::string glslVec(const glm::vec2& v);
std::string glslVec(const glm::vec4& v);

// Evaluates every case (a GL 4.1 context must be current); restores the framebuffer, viewport and
// program bindings it changed. The suite is "<lesson> GLSL". A case without a literal expected
// value takes the reference GLSL's, or where the reference is withheld (glslReferenceWithheld) the
// precomputed one for the same expression; a case with none fails, saying why.
grading::RunResult runGlslCases(const GlslExerciseSet& set);

// The student handout withholds every exercise's reference GLSL (tools/handout/sealed_shaders.txt):
// its graders and panel then use what `make handout` precomputed in the instructor's tree, the
// reference's value of each public case and its render of each public render, in
// precomputedGlslDir()/<lesson>.json (and the images beside it). True where the lesson's
// exercises_reference.glsl is withheld and absent, or setPrecomputedGlslDir forced the precomputed
// path (the grader's --precomputed=DIR: proof, in the instructor's tree, that the path grades).
bool glslReferenceWithheld(const std::string& lesson);
std::string precomputedGlslDir();  // default: sourceRoot()/tests/grading/glsl/reference
void setPrecomputedGlslDir(const std::string& dir);

// The reference's values of every case of `set` that has no literal expected value, evaluated from
// exercises_reference.glsl (a GL context current; the instructor's tree), as precomputedGlslDir's
// JSON holds them: {"lesson", "seed", "cases": [{"name", "expression", "value": [4]}]}. On a
// compile error, empty with `error` set.
std::vector<std::pair<const GlslCase*, glm::vec4>> glslReferenceValues(const GlslExerciseSet& set, std::string& error);

// True while the exercise's block of shaders/<lesson>/exercises.glsl still holds "SHADOWLAB_STUB <id>".
bool glslStubPresent(const std::string& lesson, const std::string& id);

}  // namespace shadowlab

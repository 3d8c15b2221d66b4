#pragma once
// The lesson's exercises, as the student sees them in the lesson: each with its state (stub,
// failing, passing) from the lesson's PUBLIC cases, run in-process at start and on request (the
// panel's button; GLSL exercises again whenever exercises.glsl is saved). The C++ cases are the
// doctest cases "exNN.k: ..." compiled into the lesson (tests/grading/exNN_tests.cpp), pure
// functions; the GLSL ones are app/glsl_cases.hpp's, evaluated on the GPU.
//
// A lesson opts in from declare() (the framework provides `exercises`, like `debug`):
//   exercises.add("01.1", "lightContribution: the lighting term", "every lit pixel is black");
//   exercises.addGlsl("02.4", "shadowCompare (GLSL)", "with compare=manual nothing is shadowed");
// and names the parameter that switches to the student's code (default "impl", value "student").
// With the student's code in use, a banner names each exercise still stubbed and what that does
// to the picture, and says so when the frame is (nearly) black or empty.
#include <filesystem>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "grading/cases.hpp"

namespace shadowlab {

enum class ExerciseState { NotRun, Stub, Failing, Passing, NoCases };
const char* exerciseStateName(ExerciseState s);

struct Exercise {
  std::string id;          // "01.1"
  std::string title;       // "lightContribution: the lighting term"
  std::string stubEffect;  // what an untouched stub does to the picture ("": not used live, no banner)
  bool glsl = false;       // shaders/NN_name/exercises.glsl, else lessons/NN_name/exercises.cpp
  std::string usedWhen;    // GLSL: "filter=pcf_nxn", the view that calls it ("": every view)
  ExerciseState state = ExerciseState::NotRun;
  int passed = 0, cases = 0;
  bool markerLeft = false;   // passing, but the SHADOWLAB_STUB line is still there
  std::string firstFailure;  // the first failing case's name and output

  // The function to write: the title up to its first ':' or space ("slopeScaledBias").
  std::string function() const;
};

// The banner of the student handout and the browser, where the preprocessor put the student's
// exercises.glsl in place of withheld reference GLSL (core/shader_files.hpp, withheldReplaced()):
// whose code draws, which of its exercises are still stubs, and where the reference's pictures are.
// Only while the view calls one of them (`inUse`: the ids of the lesson's GLSL exercises whose
// usedWhen holds). "" for none.
std::string withheldBanner(const std::vector<std::string>& replaced, const std::vector<std::string>& inUse,
                           const std::string& lesson);

// Where a student writes exercise `e` of `lesson` ("03_shadow_quality"): the repository-relative
// file (lessons/NN_name/exercises.cpp or shaders/NN_name/exercises.glsl) and the line of its
// "EXERCISE NN.k" tag in the source tree (0 when the tag is not found).
struct ExerciseLocation {
  std::string file;
  int line = 0;
  std::string text() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};
ExerciseLocation exerciseLocation(const std::string& lesson, const Exercise& e);
// The one command that builds what changed and grades lesson `lesson`'s exercises.
std::string gradeCommand(const std::string& lesson);

class Exercises {
 public:
  void add(std::string id, std::string title, std::string stubEffect);
  // usedWhen: "name=value", the parameter value whose view calls the function ("": every view).
  void addGlsl(std::string id, std::string title, std::string stubEffect, std::string usedWhen = "");
  // The parameter (a choice) whose value `student` means "the student's code": impl=student.
  void switchedBy(std::string param, std::string studentValue = "student");
  bool empty() const { return list_.empty(); }
  const std::vector<Exercise>& list() const { return list_; }
  const std::string& param() const { return param_; }
  const std::string& studentValue() const { return studentValue_; }

  // The framework's side. evaluate() runs the public cases (a GL context must be current for the
  // GLSL ones); glslChanged() is true when exercises.glsl was saved since.
  void evaluate(const std::string& lesson);
  bool glslChanged() const;
  // Per exercise its state line ("01.1  stub     lightContribution: ... (0 of 5 public cases
  // pass)"), then where to write it (file:line, function) and, when it fails, its first failing
  // case; last, the command that grades the lesson and the switch that shows the student's code.
  std::string report() const;
  // The GLSL exercises the view with these parameters calls (their usedWhen holds). Throws
  // ParamError when a usedWhen names no parameter of the lesson.
  std::vector<std::string> glslInUse(const ParamRegistry& params) const;
  // The banner while the student's code is in use: empty when no exercise is a stub.
  std::string stubBanner(double blackShare) const;

 private:
  void apply(const grading::RunResult& run, bool glsl);
  std::vector<Exercise> list_;
  std::string param_ = "impl", studentValue_ = "student", lesson_;
  std::filesystem::file_time_type glslStamp_{};
};

}  // namespace shadowlab

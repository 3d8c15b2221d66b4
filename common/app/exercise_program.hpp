#pragma once
// A lesson program that calls GLSL exercises: two builds of the same files. The reference build
// includes the lesson's exercises_reference.glsl; the student's defines SHADOWLAB_STUDENT_GLSL,
// which makes the shader include exercises.glsl instead:
//
//   #ifdef SHADOWLAB_STUDENT_GLSL
//   #include "exercises.glsl"
//   #else
//   #include "exercises_reference.glsl"
//   #endif
//
// get(defines) is the variant impl selects (gl::ProgramVariants: specialised per define set),
// built on first use, hot-reloaded when either file changes. Only the builds in use can stop a
// frame or a headless run: a student file that does not compile shows its error (file:line) while
// impl=reference keeps working, and with impl=student a headless run exits 1 naming the error
// (the GLSL graders score that 0). For a single program, the ExerciseProgram stands in for
// gl::Program (use, set, location, the conversion for gl::drawScene): get({}).
#include <functional>
#include <string>
#include <vector>

#include "gl/program.hpp"

namespace shadowlab {

class ExerciseProgram {
 public:
  ExerciseProgram(const std::string& label, const std::vector<std::string>& files, std::function<bool()> student)
      : student_(std::move(student)),
        reference_(label, files),
        studentBuild_(label + " (student GLSL)", files, {"SHADOWLAB_STUDENT_GLSL"}) {}

  gl::Program& get(const std::vector<std::string>& defines = {}) {
    const bool student = student_();
    gl::Program& p = (student ? studentBuild_ : reference_).get(defines);
    if (student) p.setRequired([this] { return student_(); });
    else p.setRequired([this] { return !student_(); });
    return p;
  }
  // At init: the generic build of the side in use, so a broken file stops a headless run at once.
  void build() { get(); }

  operator const gl::Program&() { return get(); }
  void use() { get().use(); }
  template <class T>
  void set(const char* name, const T& v) {
    get().set(name, v);
  }
  GLint location(const char* name) { return get().location(name); }

 private:
  std::function<bool()> student_;
  gl::ProgramVariants reference_, studentBuild_;
};

}  // namespace shadowlab

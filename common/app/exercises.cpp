#include "app/exercises.hpp"

#include <algorithm>
#include <cstdio>

#include "app/glsl_cases.hpp"
#include "core/paths.hpp"

namespace shadowlab {
namespace {
std::filesystem::file_time_type glslStampOf(const std::string& lesson) {
  std::error_code ec;
  return std::filesystem::last_write_time(shaderRoot() + "/" + lesson + "/exercises.glsl", ec);
}
}  // namespace

const char* exerciseStateName(ExerciseState s) {
  switch (s) {
    case ExerciseState::NotRun: return "not run";
    case ExerciseState::Stub: return "stub";
    case ExerciseState::Failing: return "failing";
    case ExerciseState::Passing: return "passing";
    case ExerciseState::NoCases: return "no cases";
  }
  return "?";
}

void Exercises::add(std::string id, std::string title, std::string stubEffect) {
  list_.push_back({std::move(id), std::move(title), std::move(stubEffect), false});
}
void Exercises::addGlsl(std::string id, std::string title, std::string stubEffect) {
  list_.push_back({std::move(id), std::move(title), std::move(stubEffect), true});
}
void Exercises::switchedBy(std::string param, std::string studentValue) {
  param_ = std::move(param);
  studentValue_ = std::move(studentValue);
}

void Exercises::apply(const grading::RunResult& run, bool glsl) {
  for (Exercise& e : list_) {
    if (e.glsl != glsl) continue;
    e = Exercise{e.id, e.title, e.stubEffect, e.glsl};
    bool stub = false;
    for (const grading::CaseResult& c : run.cases) {
      if (c.exercise != e.id || c.hidden) continue;
      ++e.cases;
      e.passed += c.passed;
      stub = stub || c.stub;
      if (!c.passed && e.firstFailure.empty()) e.firstFailure = c.name + "\n" + c.output;
    }
    if (e.cases == 0) e.state = ExerciseState::NoCases;
    else if (e.passed == e.cases) e.state = ExerciseState::Passing;
    else e.state = stub ? ExerciseState::Stub : ExerciseState::Failing;
    e.markerLeft = stub && e.state == ExerciseState::Passing;
  }
}

void Exercises::evaluate(const std::string& lesson) {
  lesson_ = lesson;
  const bool anyCpp = std::any_of(list_.begin(), list_.end(), [](const Exercise& e) { return !e.glsl; });
  const bool anyGlsl = std::any_of(list_.begin(), list_.end(), [](const Exercise& e) { return e.glsl; });
  if (anyCpp) apply(grading::runCasesQuietly("ex" + lesson.substr(0, 2) + ".*"), false);
  if (!anyGlsl) return;
  glslStamp_ = glslStampOf(lesson);
  if (const std::optional<GlslExerciseSet> set = glslExercises(lesson, /*withHidden=*/false))
    apply(runGlslCases(*set), true);
  else apply({}, true);
}

bool Exercises::glslChanged() const {
  const bool anyGlsl = std::any_of(list_.begin(), list_.end(), [](const Exercise& e) { return e.glsl; });
  return anyGlsl && !lesson_.empty() && glslStampOf(lesson_) != glslStamp_;
}

std::string Exercises::report() const {
  std::string s;
  for (const Exercise& e : list_) {
    char line[256];
    std::snprintf(line, sizeof line, "%-5s %-8s %s%s (%d of %d public cases pass)%s\n", e.id.c_str(),
                  exerciseStateName(e.state), e.title.c_str(), e.glsl ? " [GLSL]" : "", e.passed, e.cases,
                  e.markerLeft ? "; delete its SHADOWLAB_STUB line" : "");
    s += line;
  }
  return s;
}

std::string Exercises::stubBanner(double blackShare) const {
  std::string lines;
  bool cpp = false, glsl = false;
  for (const Exercise& e : list_) {
    if (e.state != ExerciseState::Stub || e.stubEffect.empty()) continue;
    lines += "\n  " + e.id + " " + e.title + (e.glsl ? " [GLSL]" : "") + ": " + e.stubEffect;
    (e.glsl ? glsl : cpp) = true;
  }
  if (lines.empty()) return lines;
  std::string s = param_ + "=" + studentValue_ + ": your code is still a stub" + lines;
  if (blackShare > 0.95) {
    char pct[16];
    std::snprintf(pct, sizeof pct, "%.0f", 100 * blackShare);
    s += "\nThe frame is " + std::string(pct) + "% black or empty: that is the stub, not a bug in the lesson.";
  }
  const std::string files = std::string(cpp ? "lessons/" + lesson_ + "/exercises.cpp" : "") +
                            (cpp && glsl ? " and " : "") + (glsl ? "shaders/" + lesson_ + "/exercises.glsl" : "");
  return s + "\nWrite them in " + files + ", or set " + param_ + "=reference.";
}

}  // namespace shadowlab

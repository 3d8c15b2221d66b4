#include "app/exercises.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <regex>

#include "app/glsl_cases.hpp"
#include "core/paths.hpp"
#include "core/shader_files.hpp"

namespace shadowlab {
namespace {
std::filesystem::file_time_type glslStampOf(const std::string& lesson) {
  std::error_code ec;
  return std::filesystem::last_write_time(shaderRoot() + "/" + lesson + "/exercises.glsl", ec);
}
}  // namespace

std::string Exercise::function() const { return title.substr(0, title.find_first_of(": ")); }

ExerciseLocation exerciseLocation(const std::string& lesson, const Exercise& e) {
  ExerciseLocation at{(e.glsl ? "shaders/" : "lessons/") + lesson + (e.glsl ? "/exercises.glsl" : "/exercises.cpp")};
  std::ifstream in(sourceRoot() + "/" + at.file);
  const std::string tag = "EXERCISE " + e.id;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::size_t i = line.find(tag);
    if (i == std::string::npos) continue;
    const std::size_t end = i + tag.size();
    if (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) continue;  // 03.1 is not 03.10
    at.line = n;
    break;
  }
  return at;
}

std::string gradeCommand(const std::string& lesson) { return "make grade LESSON=" + lesson.substr(0, 2); }

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
void Exercises::addGlsl(std::string id, std::string title, std::string stubEffect, std::string usedWhen) {
  list_.push_back({std::move(id), std::move(title), std::move(stubEffect), true});
  list_.back().usedWhen = std::move(usedWhen);
}

std::vector<std::string> Exercises::glslInUse(const ParamRegistry& params) const {
  std::vector<std::string> ids;
  for (const Exercise& e : list_) {
    if (!e.glsl) continue;
    const auto eq = e.usedWhen.find('=');
    if (eq == std::string::npos || params.get(e.usedWhen.substr(0, eq)) == e.usedWhen.substr(eq + 1))
      ids.push_back(e.id);
  }
  return ids;
}
void Exercises::switchedBy(std::string param, std::string studentValue) {
  param_ = std::move(param);
  studentValue_ = std::move(studentValue);
}

void Exercises::apply(const grading::RunResult& run, bool glsl) {
  for (Exercise& e : list_) {
    if (e.glsl != glsl) continue;
    e.state = ExerciseState::NotRun;  // the results afresh; what the lesson declared stays
    e.passed = e.cases = 0;
    e.markerLeft = false;
    e.firstFailure.clear();
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
    s += "      write " + e.function() + " in " + exerciseLocation(lesson_, e).text() + "\n";
    if (e.state != ExerciseState::Failing) continue;
    std::string failure = e.firstFailure;  // indented under the exercise, at most 6 lines
    std::size_t at = 0;
    for (int n = 0; n < 6 && at < failure.size(); ++n) {
      const std::size_t end = std::min(failure.find('\n', at), failure.size());
      s += "      | " + failure.substr(at, end - at) + "\n";
      at = end + 1;
    }
  }
  if (list_.empty()) return s;
  return s + "Grade them (this builds what changed first): " + gradeCommand(lesson_) + "\nSee yours live: --set " +
         param_ + "=" + studentValue_ + "\n";
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

std::string withheldBanner(const std::vector<std::string>& replaced, const std::vector<std::string>& inUse,
                           const std::string& lesson) {
  std::string s;
  const std::regex marker(R"(SHADOWLAB_STUB ([0-9]+\.[0-9]+))");
  for (const std::string& path : replaced) {
    // The lesson's own file: only the exercises its view calls. Another lesson's (included): all.
    const bool own = path.rfind(lesson + "/", 0) == 0;
    const auto called = [&](const std::string& id) {
      return !own || std::find(inUse.begin(), inUse.end(), id) != inUse.end();
    };
    if (own && std::none_of(inUse.begin(), inUse.end(),
                            [&](const std::string& id) { return id.rfind(lesson.substr(0, 2) + ".", 0) == 0; }))
      continue;  // the view calls none of the file's exercises: the reference is not missed
    std::ifstream in(shaderRoot() + "/" + withheldStandIn(path));
    std::string stubs;
    std::smatch m;
    for (std::string line; std::getline(in, line);)
      if (std::regex_search(line, m, marker) && called(m[1].str())) stubs += (stubs.empty() ? "" : ", ") + m[1].str();
    s += "\n  shaders/" + withheldStandIn(path) + (stubs.empty() ? ": your answers" : ": " + stubs + " still a stub");
  }
  if (s.empty()) return "";
  const std::string golden = "tests/data/golden/" + lesson + "/";
  const bool pictures = std::filesystem::exists(sourceRoot() + "/" + golden);  // not in the browser
  return "Answers withheld here (the student handout, the browser): your GLSL draws where the reference's is withheld" +
         s + (pictures ? "\nF4: the reference's picture of the preset in view (" + golden + ")" : "");
}

}  // namespace shadowlab

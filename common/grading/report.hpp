#pragma once
// Grades and the files graders write, from one or more runs (cases.hpp):
//   results JSON   every case of every run (name, exercise, file, passed, hidden, output); the
//                  input of grade_report, which merges runs (C++ graders, GLSL graders)
//   score JSON     per exercise: cases passed and failed (public and hidden), score, points;
//                  the overall score and the seeds
//   JUnit XML      one <testcase> per case (tests= counts cases), repository-relative
//                  classnames, the score as properties
//   results.json   the format Gradescope's autograder reads: per test name, score, max_score,
//                  status, output and visibility (hidden cases "after_published"), and the total
//
// Scoring: every exercise is worth kPointsPerExercise, shared equally by its cases (public and
// hidden alike); a case earns its share only when it passes. An untouched stub fails every case
// (validity.exNN.stubs proves it), so it scores 0.
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grading/cases.hpp"

namespace shadowlab::grading {
using Json = nlohmann::ordered_json;
}

namespace shadowlab::grading {

constexpr double kPointsPerExercise = 10.0;

struct ExerciseGrade {
  std::string id;  // "01.1"
  int passed = 0, failed = 0;
  int hiddenPassed = 0, hiddenFailed = 0;
  bool stub = false;  // a case reached the exercise's SHADOWLAB_STUB marker
  double points = 0, maxPoints = kPointsPerExercise;
  int cases() const { return passed + failed + hiddenPassed + hiddenFailed; }
};

struct Grade {
  std::vector<ExerciseGrade> exercises;  // sorted by id
  double points = 0, maxPoints = 0;
  int cases = 0, failures = 0;  // every case of every run, exercise or not
};

Grade grade(const std::vector<RunResult>& runs);

Json resultsJson(const RunResult& run);
RunResult runFromJson(const Json& j);  // throws nlohmann::json::exception on a malformed file
// A results file: {"runs": [run, ...]}.
Json resultsJson(const std::vector<RunResult>& runs);
std::vector<RunResult> runsFromJson(const Json& j);

Json scoreJson(const std::vector<RunResult>& runs, const Grade& g);
std::string junitXml(const std::vector<RunResult>& runs, const Grade& g);
Json gradescopeJson(const std::vector<RunResult>& runs, const Grade& g);

// Writes `text` to `path` (creating its folder); false when it cannot.
bool writeFile(const std::string& path, const std::string& text);

// The files a grader writes; an empty path is not written.
struct ReportFiles {
  std::string results, score, junit, gradescope;
};
// Writes every file named; prints the one that cannot be written to `err` and returns false.
bool writeReports(const ReportFiles& files, const std::vector<RunResult>& runs, std::ostream& err);

// Grader validity on untouched stubs: every exercise case must fail (a stub scores 0). Prints each
// exercise's verdict to `out` and each case that passes anyway to `err`; true when none does.
bool stubsScoreZero(const std::vector<RunResult>& runs, std::ostream& out, std::ostream& err);

// Whether a hidden render at a random placement can grade a GLSL answer, from the reference run's
// ground-truth figures (the lesson's --measure file): at least 2% of the view in shadow and 2% lit
// (hard), or 0.5% umbra and 2% not (soft). A stub that answers "lit" (or "shadowed") everywhere then
// differs from the reference on 0.5% of the view or more, five times the renders' tolerance. `why`
// gets the figures in words. False for figures that are not there.
bool renderInformative(const nlohmann::json& figures, std::string& why);

}  // namespace shadowlab::grading

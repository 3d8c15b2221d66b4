// grade_report --out DIR [--reference-calls=FILE] [--build-failed=LOG] RESULTS.json...
//
// --reference-calls=FILE: exercises that borrowed the reference answer (tools/grading/
// reference_reach.sh: one "NN.k<TAB>why" a line): every case of each scores 0, with why.
// Merges the results files that graders write (--results-json: grade_exNN, grade_exNN_glsl) into
// one grade. --build-failed=LOG applies to the next file: a run of the reference grader standing
// in for a student's grader that did not compile; each of its cases counts as failed, with LOG
// (the compiler's errors) as the reason. The grade: DIR/score.json (per exercise, public and hidden cases, points,
// seeds), DIR/junit.xml and DIR/results.json, the file Gradescope's autograder reads. Prints one line per exercise.
// Exit 0 when written (whatever the score), 1 on an unreadable or malformed results file, 2 on
// bad usage.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "grading/report.hpp"

using namespace shadowlab::grading;

namespace {
// The student's grader did not build: every case fails with the compiler's first errors.
void failAll(RunResult& run, const std::string& logPath) {
  std::ifstream in(logPath);
  std::string text, line;
  for (int n = 0; n < 40 && std::getline(in, line); ++n) text += line + "\n";
  run.suite += " (did not compile)";
  for (CaseResult& c : run.cases) {
    c.passed = false;
    c.stub = false;
    c.partialCredit = false;  // the reference's checks held, not the student's
    c.output = "your exercises.cpp does not compile, so no case could run:\n" + text;
  }
}

// Exercises found calling into the reference answer: every case fails, the reason first. Returns
// false (and says why) when FILE cannot be read or a line is not "NN.k<TAB>why".
bool failBorrowed(std::vector<RunResult>& runs, const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::cerr << "grade_report: cannot read --reference-calls file " << path << "\n", false;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.empty()) continue;
    const std::size_t tab = line.find('\t');
    const std::string id = line.substr(0, tab);
    if (tab == std::string::npos || id.size() < 4 || id.find('.') == std::string::npos) {
      std::cerr << "grade_report: " << path << ":" << n << ": expected 'NN.k<TAB>why', found '" << line << "'\n";
      return false;
    }
    for (RunResult& run : runs)
      for (CaseResult& c : run.cases)
        if (c.exercise == id) {
          c.passed = false;
          c.stub = false;
          c.partialCredit = false;
          c.output =
              "exercise " + id + " scores 0: " + line.substr(tab + 1) + (c.output.empty() ? "" : "\n" + c.output);
        }
  }
  return true;
}

// Under a failing exercise that is not a stub: its first failing public case, the name and the
// first lines of why (inputs, expected, actual), so `make grade` alone shows what to fix.
void printFirstFailure(const std::vector<RunResult>& runs, const std::string& id) {
  for (const RunResult& run : runs)
    for (const CaseResult& c : run.cases) {
      if (c.exercise != id || c.passed || c.hidden) continue;
      std::cout << "    first failing case: " << c.name << "\n";
      std::size_t at = 0;
      for (int n = 0; n < 8 && at < c.output.size(); ++n) {
        const std::size_t end = std::min(c.output.find('\n', at), c.output.size());
        std::cout << "    | " << c.output.substr(at, end - at) << "\n";
        at = end + 1;
      }
      return;
    }
}
}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: grade_report --out DIR [--reference-calls=FILE] [--build-failed=LOG] RESULTS.json...\n";
  std::string out, failedLog, borrowed;
  std::vector<std::pair<std::string, std::string>> inputs;  // results file, build log ("" when it built)
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      return 0;
    } else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a.rfind("--build-failed=", 0) == 0) failedLog = a.substr(15);
    else if (a.rfind("--reference-calls=", 0) == 0) borrowed = a.substr(18);
    else if (a.rfind("--", 0) == 0) {
      std::cerr << "grade_report: unknown flag '" << a
                << "'; valid: --out DIR, --reference-calls=FILE, --build-failed=LOG\n";
      return 2;
    } else {
      inputs.push_back({a, failedLog});
      failedLog.clear();
    }
  }
  if (out.empty() || inputs.empty()) {
    std::cerr << usage;
    return 2;
  }
  std::vector<RunResult> runs;
  for (const auto& [path, log] : inputs) {
    std::ifstream in(path);
    if (!in) {
      std::cerr << "grade_report: cannot read " << path << "\n";
      return 1;
    }
    try {
      for (RunResult& r : runsFromJson(Json::parse(in))) {
        if (!log.empty()) failAll(r, log);
        runs.push_back(std::move(r));
      }
    } catch (const std::exception& e) {
      std::cerr << "grade_report: " << path << ": not a results file (" << e.what() << ")\n";
      return 1;
    }
  }
  if (!borrowed.empty() && !failBorrowed(runs, borrowed)) return 1;
  if (!writeReports({"", out + "/score.json", out + "/junit.xml", out + "/results.json"}, runs, std::cerr)) return 1;
  const Grade g = grade(runs);
  for (const ExerciseGrade& e : g.exercises) {
    std::cout << "exercise " << e.id << ": " << e.points << " / " << e.maxPoints << " points, "
              << e.passed + e.hiddenPassed << " of " << e.cases() << " cases (" << e.hiddenPassed + e.hiddenFailed
              << " hidden)" << (e.stub ? ", still a stub" : "") << "\n";
    if (!e.stub && e.failed > 0) printFirstFailure(runs, e.id);
  }
  std::cout << "score " << g.points << " / " << g.maxPoints << "; " << out
            << "/{score.json, junit.xml, results.json}\n";
  return 0;
}

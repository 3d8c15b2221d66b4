// grade_report --out DIR RESULTS.json...
//
// Merges the results files that graders write (--results-json: grade_exNN, grade_exNN_glsl) into
// one grade: DIR/score.json (per exercise, public and hidden cases, points, seeds), DIR/junit.xml
// and DIR/results.json, the file Gradescope's autograder reads. Prints one line per exercise.
// Exit 0 when written (whatever the score), 1 on an unreadable or malformed results file, 2 on
// bad usage.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "grading/report.hpp"

using namespace shadowlab::grading;

int main(int argc, char** argv) {
  std::string out;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a.rfind("--", 0) == 0) {
      std::cerr << "grade_report: unknown flag '" << a << "'; valid: --out DIR\n";
      return 2;
    } else inputs.push_back(a);
  }
  if (out.empty() || inputs.empty()) {
    std::cerr << "usage: grade_report --out DIR RESULTS.json...\n";
    return 2;
  }
  std::vector<RunResult> runs;
  for (const std::string& path : inputs) {
    std::ifstream in(path);
    if (!in) {
      std::cerr << "grade_report: cannot read " << path << "\n";
      return 1;
    }
    try {
      for (RunResult& r : runsFromJson(Json::parse(in))) runs.push_back(std::move(r));
    } catch (const std::exception& e) {
      std::cerr << "grade_report: " << path << ": not a results file (" << e.what() << ")\n";
      return 1;
    }
  }
  if (!writeReports({"", out + "/score.json", out + "/junit.xml", out + "/results.json"}, runs, std::cerr)) return 1;
  const Grade g = grade(runs);
  for (const ExerciseGrade& e : g.exercises)
    std::cout << "exercise " << e.id << ": " << e.points << " / " << e.maxPoints << " points, "
              << e.passed + e.hiddenPassed << " of " << e.cases() << " cases (" << e.hiddenPassed + e.hiddenFailed
              << " hidden)" << (e.stub ? ", still a stub" : "") << "\n";
  std::cout << "score " << g.points << " / " << g.maxPoints << "; " << out
            << "/{score.json, junit.xml, results.json}\n";
  return 0;
}

// The main() of every doctest binary (graders, unit, stress, gpu): our flags, then doctest.
//   --seed=N                       seed of the randomised cases (also SHADOWLAB_SEED)
//   --hidden-seed=N                the hidden cases' own seed (grading a submission: the public
//                                  cases keep the seed the student ran them with)
//   --results-json=FILE            every case's result (grade_report merges such files)
//   --score-json=FILE  --junit=FILE  --gradescope=FILE
//                                  the score per exercise, JUnit XML, Gradescope's results.json
//   --answers-record=FILE          the student's process of a graded run: the exercise functions
//                                  answers are kept in FILE, its own checks decide nothing
//   --answers-replay=FILE          the judging process (a reference grader): each call of an
//                                  exercise function returns the answer FILE recorded
//                                  (grading/answers.hpp; tools/grading/grade_isolated runs both)
//   --expect-stub-scores-zero      grader validity on the untouched stubs: every case of every
//                                  exercise must fail (an untouched stub earns nothing)
// A run that executes no test case at all fails: a ctest entry whose filter matches nothing (a
// name split at ';', a renamed case) must never pass silently.
#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "grading/answers.hpp"
#include "grading/cases.hpp"
#include "grading/report.hpp"

using namespace shadowlab;

namespace {

bool parseSeed(const char* text, std::uint64_t& out) {
  char* end = nullptr;
  unsigned long long v = std::strtoull(text, &end, 10);
  if (end == text || *end != '\0' || text[0] == '-') return false;
  out = v;
  return true;
}

struct Options {
  std::string resultsJson, scoreJson, junit, gradescope, answersRecord, answersReplay;
  bool expectStubsScoreZero = false;
  std::vector<char*> doctestArgs;
};

bool takeValue(const char* arg, const char* flag, std::string& out) {
  const std::size_t n = std::strlen(flag);
  if (std::strncmp(arg, flag, n) != 0) return false;
  out = arg + n;
  return true;
}

// Returns 0 when parsed, else the exit code.
int parse(int argc, char** argv, Options& o) {
  if (const char* env = std::getenv("SHADOWLAB_SEED")) {
    std::uint64_t s = 0;
    if (!parseSeed(env, s)) {
      std::cerr << "SHADOWLAB_SEED='" << env << "' is not a non-negative integer\n";
      return 2;
    }
    grading::setSeed(s);
  }
  for (int i = 0; i < argc; ++i) {
    std::string value;
    if (takeValue(argv[i], "--results-json=", o.resultsJson) || takeValue(argv[i], "--score-json=", o.scoreJson) ||
        takeValue(argv[i], "--junit=", o.junit) || takeValue(argv[i], "--gradescope=", o.gradescope) ||
        takeValue(argv[i], "--answers-record=", o.answersRecord) ||
        takeValue(argv[i], "--answers-replay=", o.answersReplay))
      continue;
    if (std::strcmp(argv[i], "--expect-stub-scores-zero") == 0) {
      o.expectStubsScoreZero = true;
      continue;
    }
    bool isSeed = false;
    for (auto [flag, set] :
         {std::pair{"--seed=", &grading::setSeed}, std::pair{"--hidden-seed=", &grading::setHiddenSeed}}) {
      if (!takeValue(argv[i], flag, value)) continue;
      std::uint64_t s = 0;
      if (!parseSeed(value.c_str(), s)) {
        std::cerr << std::string(flag, std::strlen(flag) - 1) << "='" << value << "' is not a non-negative integer\n";
        return 2;
      }
      set(s);
      isSeed = true;
    }
    if (isSeed) continue;
    o.doctestArgs.push_back(argv[i]);
  }
  if (!o.answersRecord.empty() && !o.answersReplay.empty()) {
    std::cerr << "--answers-record and --answers-replay: one process either answers or judges, not both\n";
    return 2;
  }
  std::string error;
  if (!o.answersReplay.empty() && !grading::replayAnswersFrom(o.answersReplay, error)) {
    std::cerr << "--answers-replay: " << error << "\n";
    return 2;
  }
  if (!o.answersRecord.empty()) grading::recordAnswersTo(o.answersRecord);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (int e = parse(argc, argv, o)) return e;
  doctest::Context context(static_cast<int>(o.doctestArgs.size()), o.doctestArgs.data());
  bool listing = false;  // test discovery parses stdout: print nothing extra then
  for (char* arg : o.doctestArgs)
    listing = listing || std::strncmp(arg, "--list", 6) == 0 || std::strncmp(arg, "-l", 2) == 0 ||
              std::strncmp(arg, "-ltc", 4) == 0 || std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0;
  if (!listing)
    std::cout << "[shadowlab] seed " << grading::seed() << " (replay with --seed=" << grading::seed()
              << " or SHADOWLAB_SEED)"
              << (grading::hiddenSeed() != grading::seed() ? "; hidden cases with their own seed" : "") << "\n";
  const int result = context.run();
  if (listing || context.shouldExit()) return result;
  if (std::string error; !grading::writeRecordedAnswers(error)) {
    std::cerr << "[shadowlab] " << error << "\n";
    return 1;
  }

  grading::RunResult run = grading::lastRun();
  run.suite = std::filesystem::path(argv[0]).filename().string();
  run.seed = grading::seed();
  run.hiddenSeed = grading::hiddenSeed();
  if (!grading::writeReports({o.resultsJson, o.scoreJson, o.junit, o.gradescope}, {run}, std::cerr)) return 1;
  if (run.testCasesRun == 0) {
    std::cerr << "[shadowlab] no test case ran: the filter matches none of this binary's cases "
                 "(a ctest entry that runs nothing must not pass)\n";
    return 1;
  }
  if (o.expectStubsScoreZero) return grading::stubsScoreZero({run}, std::cout, std::cerr) ? 0 : 1;
  return result;
}

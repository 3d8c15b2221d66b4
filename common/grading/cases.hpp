#pragma once
// Graded cases and their outcomes. A grader is a set of doctest test cases named "exNN.k: ..."
// (exercise NN.k); those in the doctest suite "hidden" exist only in the instructor's tree
// (tests/grading/hidden/) and are reported as hidden. Every run in this process (a grader's
// main, or the lesson's exercises panel running its public cases in-process) keeps one
// CaseResult per case: pass or fail, where it failed, the captured inputs, expected and actual
// values, and whether the exercise's SHADOWLAB_STUB marker ran. report.hpp turns runs into
// scores, JSON, JUnit and a Gradescope results.json.
#include <cstdint>
#include <string>
#include <vector>

// TEST_CASE("ex03.1: ..." * SHADOWLAB_INDEPENDENT_CHECKS): the case's checks are separate
// situations (six hand-worked inputs), so each that holds earns its share of the case.
#define SHADOWLAB_INDEPENDENT_CHECKS doctest::description(::shadowlab::grading::kIndependentChecks)

namespace shadowlab::grading {

inline constexpr const char* kIndependentChecks = "independent checks: partial credit";

struct CaseResult {
  std::string exercise;  // "01.1"; "" for a case that belongs to no exercise
  std::string name;      // the test case's full name
  std::string file;      // repository-relative source of the case
  int line = 0;
  bool passed = false;
  bool hidden = false;  // doctest suite "hidden": instructor-only
  bool stub = false;    // the exercise's SHADOWLAB_STUB marker ran during the case
  std::string output;   // why it failed: location, check, captured inputs (a few lines); "" when passed
  // A case whose checks are independent (SHADOWLAB_INDEPENDENT_CHECKS) earns the share of them that
  // held; any other case, and one that threw or reached a stub, all or nothing.
  bool partialCredit = false;
  int checks = 0, checksFailed = 0;
};

// The credit a case earns, 0..1: 1 passed, the share of its checks that held for a partial-credit
// case that ran to its end without reaching a stub, else 0.
double caseCredit(const CaseResult& c);

struct RunResult {
  std::string suite;  // which grader ran: "grade_ex01", "grade_ex02_glsl", ...
  std::uint64_t seed = 0;
  std::uint64_t hiddenSeed = 0;  // the hidden cases' seed (the same as seed unless set apart)
  int testCasesRun = 0;          // cases that passed the filters and ran (0 fails every run: see test_main)
  std::vector<CaseResult> cases;
};

// The seed of every randomised case: set from --seed=N or SHADOWLAB_SEED by the grader's main;
// 20261122 otherwise. Printed by graders so a failure can be replayed.
std::uint64_t seed();
void setSeed(std::uint64_t seed);
// The hidden cases' seed: --hidden-seed=N sets it apart (grading a submission: public cases with
// the seed the student ran them with, hidden ones with the assignment's), else seed().
std::uint64_t hiddenSeed();
void setHiddenSeed(std::uint64_t seed);
// A seed derived from the run's seed (the hidden seed inside a hidden case) and a case-local salt,
// so cases stay independent.
std::uint64_t seedFor(const std::string& salt);

// "ex01.1: head-on light" -> "01.1"; "" for a name that is not an exercise case.
std::string exerciseOf(const std::string& caseName);
// A path under the source tree, relative to it ("tests/grading/ex01_tests.cpp"); others unchanged.
// A relative path loses its leading "./" and "../" (compiled through ccache, __FILE__ is relative
// to the build folder inside the tree: "../../tests/grading/ex01_tests.cpp").
std::string repositoryRelative(const std::string& path);

// The cases of the latest doctest run in this process, in the order they ran.
const RunResult& lastRun();
// Runs the registered cases whose names match `filter` (doctest wildcards, e.g. "ex01.*") with no
// console output, and returns their results: the lesson's exercises panel.
RunResult runCasesQuietly(const std::string& filter);

// Appends a failure to the case running now (for graders that check outside doctest's macros).
void recordFailure(const std::string& text);

}  // namespace shadowlab::grading

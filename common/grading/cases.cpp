// The doctest runtime of every grader and test binary (DOCTEST_CONFIG_IMPLEMENT lives here, once),
// and the listener that keeps each case's result for reports and for the lessons' panels.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "grading/cases.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>

#include "core/paths.hpp"
#include "grading/stub.hpp"

namespace shadowlab::grading {
namespace {

std::uint64_t g_seed = 20261122;
std::optional<std::uint64_t> g_hiddenSeed;  // the hidden cases' own seed (--hidden-seed); else g_seed
RunResult g_run;
constexpr int kShownFailures = 3;  // per case: enough to see the pattern, not a page of output

struct CaseState {
  bool active = false;
  int failures = 0;
  bool threw = false;
};
CaseState g_case;

std::string contextLines() {
  std::ostringstream out;
  const int n = doctest::IReporter::get_num_active_contexts();
  const doctest::IContextScope* const* contexts = doctest::IReporter::get_active_contexts();
  for (int i = 0; i < n; ++i) {
    std::ostringstream one;
    contexts[i]->stringify(&one);
    out << "\n  " << one.str();
  }
  return out.str();
}

void addFailure(const std::string& text) {
  if (!g_case.active || g_run.cases.empty()) return;
  CaseResult& c = g_run.cases.back();
  ++g_case.failures;
  if (g_case.failures > kShownFailures) return;
  if (!c.output.empty()) c.output += '\n';
  c.output += text + contextLines();
}

// Keeps every case's outcome; registered as a listener (beside the console reporter) and as the
// quiet reporter the panel runs with.
struct CaseRecorder : doctest::IReporter {
  explicit CaseRecorder(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats& stats) override {
    g_run.testCasesRun = int(stats.numTestCasesPassingFilters);
  }
  void test_case_start(const doctest::TestCaseData& tc) override {
    CaseResult c;
    c.name = tc.m_name;
    c.exercise = exerciseOf(c.name);
    c.file = repositoryRelative(tc.m_file.c_str());
    c.line = int(tc.m_line);
    c.hidden = std::string(tc.m_test_suite) == "hidden";
    c.partialCredit = tc.m_description && std::string(tc.m_description) == kIndependentChecks;
    g_run.cases.push_back(std::move(c));
    g_case = {true, 0, false};
    clearStubsReached();
  }
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats& stats) override {
    if (g_run.cases.empty()) return;
    CaseResult& c = g_run.cases.back();
    c.passed = stats.testCaseSuccess;
    c.stub = !c.exercise.empty() && stubsReached().count(c.exercise) > 0;
    c.checks = stats.numAssertsCurrentTest;
    c.checksFailed = stats.numAssertsFailedCurrentTest;
    c.partialCredit = c.partialCredit && !g_case.threw;  // checks that never ran cannot be counted
    if (g_case.failures > kShownFailures)
      c.output += "\n(" + std::to_string(g_case.failures - kShownFailures) + " more failed checks in this case)";
    if (!c.passed && c.output.empty()) c.output = "failed";
    g_case.active = false;
  }
  void test_case_exception(const doctest::TestCaseException& e) override {
    g_case.threw = true;
    addFailure(std::string(e.is_crash ? "crashed: " : "threw: ") + e.error_string.c_str());
  }
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData& a) override {
    if (!a.m_failed) return;
    std::string text = repositoryRelative(a.m_file) + ":" + std::to_string(a.m_line) + ": ";
    if (a.m_threw) text += std::string(a.m_expr) + " threw " + a.m_exception.c_str();
    else text += std::string(doctest::assertString(a.m_at)) + "( " + a.m_expr + " ) is false: " + a.m_decomp.c_str();
    addFailure(text);
  }
  void log_message(const doctest::MessageData& m) override {
    if (m.m_severity & doctest::assertType::is_warn) return;  // MESSAGE / WARN: not a failure
    addFailure(repositoryRelative(m.m_file) + ":" + std::to_string(m.m_line) + ": " + m.m_string.c_str());
  }
  void test_case_skipped(const doctest::TestCaseData&) override {}
};
DOCTEST_REGISTER_LISTENER("shadowlab-cases", 1, CaseRecorder);

// Prints nothing: the listener above does the recording.
struct QuietReporter : CaseRecorder {
  using CaseRecorder::CaseRecorder;
  void test_run_end(const doctest::TestRunStats&) override {}
  void test_case_start(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
};
DOCTEST_REGISTER_REPORTER("shadowlab-quiet", 1, QuietReporter);

}  // namespace

std::uint64_t seed() { return g_seed; }
void setSeed(std::uint64_t s) { g_seed = s; }
std::uint64_t hiddenSeed() { return g_hiddenSeed.value_or(g_seed); }
void setHiddenSeed(std::uint64_t s) { g_hiddenSeed = s; }
std::uint64_t seedFor(const std::string& salt) {
  const bool hidden = g_case.active && !g_run.cases.empty() && g_run.cases.back().hidden;
  return (hidden ? hiddenSeed() : g_seed) ^ (std::hash<std::string>{}(salt)*0x9E3779B97F4A7C15ull);
}

double caseCredit(const CaseResult& c) {
  if (c.passed) return 1.0;
  if (!c.partialCredit || c.stub || c.checks <= 0) return 0.0;
  return double(std::max(0, c.checks - c.checksFailed)) / double(c.checks);
}

std::string exerciseOf(const std::string& name) {
  if (name.rfind("ex", 0) != 0) return "";
  const auto end = name.find_first_of(": ", 2);
  if (end == std::string::npos || end == 2) return "";
  return name.substr(2, end - 2);
}

std::string repositoryRelative(const std::string& path) {
  const std::string root = configuredSourceRoot() + "/";
  if (path.rfind(root, 0) == 0) return path.substr(root.size());
  if (path.empty() || path.front() == '/') return path;
  std::size_t start = 0;
  while (path.compare(start, 2, "./") == 0 || path.compare(start, 3, "../") == 0)
    start += path.compare(start, 2, "./") == 0 ? 2 : 3;
  return path.substr(start);
}

const RunResult& lastRun() { return g_run; }

void recordFailure(const std::string& text) { addFailure(text); }

RunResult runCasesQuietly(const std::string& filter) {
  const RunResult saved = g_run;
  g_run = RunResult{};
  g_run.seed = g_seed;
  g_run.hiddenSeed = hiddenSeed();
  doctest::Context context;
  context.setOption("reporters", "shadowlab-quiet");
  context.setOption("test-case", filter.c_str());
  context.setOption("no-breaks", true);
  context.run();
  RunResult result = std::move(g_run);
  g_run = saved;
  return result;
}

}  // namespace shadowlab::grading

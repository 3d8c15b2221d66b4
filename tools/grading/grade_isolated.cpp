// grade_isolated --reference=REFERENCE_GRADER --results-json=FILE [--timeout=SECONDS] [--memory-mb=MB]
//                -- GRADER [GRADER ARGS...]
//
// Runs a student's grader (grade_exNN) one exercise at a time, each in a process of its own with a
// time limit (default 60 s) and a memory limit (default 2048 MiB), so that a crash, an endless
// loop or a runaway allocation in one exercise costs that exercise and nothing else: its cases
// score 0 with the reason ("crashed with SIGSEGV in case 'ex01.3: ...'"), every other exercise is
// graded as usual. FILE gets the merged results, the same format a grader's --results-json writes
// (grade_report reads it).
//
// Which cases there are comes from REFERENCE_GRADER (grade_exNN_reference: the same cases compiled
// against the reference implementation), so listing them runs no student code: a student's static
// initialiser that crashes cannot hide an exercise.
//
// The trust boundary (common/grading/answers.hpp): the student's process only answers. It runs the
// exercise's cases with --answers-record, keeping what each exercise function returned (or threw);
// its own checks and exit code decide nothing, and it is given no results file to write. Then
// REFERENCE_GRADER, which holds no student code, runs the same cases with --answers-replay (each
// call of an exercise function returns the recorded answer) and decides every check and writes
// the results, which this process reads before the next exercise starts. The student's process
// runs in a process group of its own that is killed when it ends, so nothing it started is left to
// rewrite a file afterwards. (A sandbox against reading or writing files while it runs is the
// operating system's: run graders as a user of their own, or in a container as Gradescope does.)
// Exit 0 when FILE was written, 1 when the reference grader cannot list its cases, 2 on bad usage.
#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/process.hpp"
#include "grading/cases.hpp"
#include "grading/report.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;
using namespace shadowlab::grading;

namespace {

struct Options {
  std::string reference, results, grader;
  std::vector<std::string> graderArgs;
  double timeout = 60;
  std::size_t memoryMb = 2048;
};

const char* kUsage =
    "usage: grade_isolated --reference=REFERENCE_GRADER --results-json=FILE [--timeout=SECONDS] "
    "[--memory-mb=MB] -- GRADER [ARGS...]\n";

bool parse(int argc, char** argv, Options& o) {
  int i = 1;
  for (; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* flag, std::string& out) {
      if (a.rfind(flag, 0) != 0) return false;
      out = a.substr(std::string(flag).size());
      return true;
    };
    std::string number;
    if (a == "--") break;
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (value("--reference=", o.reference) || value("--results-json=", o.results)) continue;
    if (value("--timeout=", number)) {
      o.timeout = std::atof(number.c_str());
      if (!(o.timeout > 0)) return std::cerr << "grade_isolated: --timeout=" << number << " is not a time > 0\n", false;
    } else if (value("--memory-mb=", number)) {
      o.memoryMb = std::size_t(std::atoll(number.c_str()));
      if (o.memoryMb < 64) return std::cerr << "grade_isolated: --memory-mb=" << number << " is under 64\n", false;
    } else {
      std::cerr << "grade_isolated: unknown argument '" << a << "'\n";
      return false;
    }
  }
  if (i + 1 >= argc || o.reference.empty() || o.results.empty()) return false;
  o.grader = argv[i + 1];
  for (int k = i + 2; k < argc; ++k) o.graderArgs.push_back(argv[k]);
  return true;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The case names a grader lists (doctest --list-test-cases), optionally of one test suite.
bool listCases(const std::string& grader, const std::string& suite, const fs::path& scratch,
               std::vector<std::string>& names) {
  std::vector<std::string> args = {grader, "--list-test-cases"};
  if (!suite.empty()) args.push_back("--test-suite=" + suite);
  ProcessOptions o;
  o.stdoutPath = (scratch / "list.txt").string();
  o.stderrPath = (scratch / "list.err").string();
  o.timeoutSeconds = 60;
  if (runProcess(args, o) != 0) return false;
  std::istringstream lines(slurp(o.stdoutPath));
  for (std::string line; std::getline(lines, line);)
    if (!exerciseOf(line).empty()) names.push_back(line);
  return true;
}

std::string signalName(int signal) {
  static const std::map<int, std::string> names = {{SIGSEGV, "SIGSEGV (a bad pointer or a stack overflow)"},
                                                   {SIGABRT, "SIGABRT (an uncaught exception or a failed assert)"},
                                                   {SIGFPE, "SIGFPE (an integer division by zero)"},
                                                   {SIGILL, "SIGILL"}};
  const auto it = names.find(signal);
  return it != names.end() ? it->second : "signal " + std::to_string(signal);
}

// The case doctest was running when the process died (it prints "TEST CASE:  name" on a crash).
std::string crashedCase(const std::string& log) {
  const auto at = log.rfind("TEST CASE:");
  if (at == std::string::npos) return "";
  std::string name = log.substr(at + 10, log.find('\n', at) - at - 10);
  name.erase(0, name.find_first_not_of(' '));
  return name;
}

// Why the student's run of one exercise gave no answers to judge; "" when it ended on its own.
// A non-zero exit is normal (its own checks failed on its answers, which decide nothing).
std::string failure(int code, bool timedOut, const Options& o, const std::string& log) {
  if (timedOut)
    return "did not finish within " + std::to_string(int(o.timeout)) + " s (the time limit): an endless loop?";
  std::string why;
  if (code >= 128 && code < 160) why = "crashed with " + signalName(code - 128);
#ifdef _WIN32
  else if (unsigned(code) >= 0xC0000000u)
    why = "crashed (Windows exception code " + std::to_string(unsigned(code)) + ")";
#endif
  else if (code < 0) why = "could not be started";
  if (why.empty()) return "";
  if (const std::string name = crashedCase(log); !name.empty()) why += " in case '" + name + "'";
  if (code == 128 + SIGABRT || code == 128 + SIGKILL)
    why += " (the memory limit is " + std::to_string(o.memoryMb) + " MiB)";
  return why;
}

// Every case of exercise `id` failed with `why`.
std::vector<CaseResult> allFailed(const std::string& id, const std::vector<std::string>& names,
                                  const std::vector<std::string>& hidden, const std::string& why) {
  std::vector<CaseResult> cases;
  for (const std::string& name : names) {
    if (exerciseOf(name) != id) continue;
    CaseResult c;
    c.exercise = id;
    c.name = name;
    c.hidden = std::find(hidden.begin(), hidden.end(), name) != hidden.end();
    c.output = why;
    cases.push_back(c);
  }
  return cases;
}

// One exercise: the student's grader answers in a process of its own, with limits
// (--answers-record); the reference grader, which holds no student code, judges those answers
// (--answers-replay) and writes the results, read here at once.
std::vector<CaseResult> gradeExercise(const Options& o, const std::string& id, const std::vector<std::string>& names,
                                      const std::vector<std::string>& hidden, const fs::path& scratch,
                                      RunResult& merged) {
  const fs::path answers = scratch / ("ex" + id + ".answers"), log = scratch / ("ex" + id + ".log");
  const fs::path json = scratch / ("ex" + id + ".json"), judgeLog = scratch / ("ex" + id + ".judge.log");
  fs::remove(answers);
  fs::remove(json);
  const std::string filter = "--test-case=ex" + id + ":*";
  std::vector<std::string> args = {o.grader};
  args.insert(args.end(), o.graderArgs.begin(), o.graderArgs.end());
  args.insert(args.end(), {"--answers-record=" + answers.string(), filter});
  ProcessOptions p;
  p.stdoutPath = log.string();
  p.timeoutSeconds = o.timeout;
  p.memoryLimitMb = o.memoryMb;
  bool timedOut = false;
  p.timedOut = &timedOut;
  const int code = runProcess(args, p);
  if (const std::string why = failure(code, timedOut, o, slurp(log)); !why.empty()) {
    std::cout << "grade_isolated: exercise " << id << " " << why << "\n";
    return allFailed(id, names, hidden,
                     "exercise " + id + " " + why +
                         ": every case of this exercise scores 0, the other exercises were graded on their own.");
  }
  std::vector<std::string> judge = {o.reference};
  judge.insert(judge.end(), o.graderArgs.begin(), o.graderArgs.end());
  judge.insert(judge.end(), {"--answers-replay=" + answers.string(), "--results-json=" + json.string(), filter});
  ProcessOptions q;
  q.stdoutPath = judgeLog.string();
  q.timeoutSeconds = 4 * o.timeout;
  runProcess(judge, q);
  try {
    const std::vector<RunResult> runs = runsFromJson(Json::parse(slurp(json)));
    if (runs.size() == 1) {
      merged.seed = runs.front().seed;
      merged.hiddenSeed = runs.front().hiddenSeed;
      merged.testCasesRun += runs.front().testCasesRun;
      std::vector<CaseResult> cases;
      for (const CaseResult& c : runs.front().cases)
        if (c.exercise == id) cases.push_back(c);
      return cases;
    }
  } catch (const std::exception&) {}
  // The judge is ours: when it cannot judge, the answers were unreadable (the student's process
  // damaged its own file) or the grader is broken; either way nothing was earned, and we say so.
  std::cout << "grade_isolated: exercise " << id << ": the reference grader could not judge the answers ("
            << judgeLog.string() << ")\n";
  std::string detail = slurp(judgeLog);
  if (detail.size() > 400) detail.resize(400);
  return allFailed(id, names, hidden,
                   "exercise " + id +
                       ": your program's answers could not be judged (the file of answers it wrote "
                       "was missing or damaged): every case of this exercise scores 0.\n" +
                       detail);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::cerr << kUsage;
    return 2;
  }
  const fs::path scratch = fs::path(o.results).parent_path() / (fs::path(o.results).stem().string() + ".isolated");
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  std::vector<std::string> names, hidden;
  if (!listCases(o.reference, "", scratch, names) || !listCases(o.reference, "hidden", scratch, hidden) ||
      names.empty()) {
    std::cerr << "grade_isolated: " << o.reference << " cannot list its cases (" << scratch.string() << "/list.err)\n";
    return 1;
  }
  std::vector<std::string> exercises;
  for (const std::string& n : names)
    if (std::find(exercises.begin(), exercises.end(), exerciseOf(n)) == exercises.end())
      exercises.push_back(exerciseOf(n));

  RunResult merged;
  merged.suite = fs::path(o.grader).filename().string();
  merged.seed = seed();  // replaced by the judge's (--seed=N, SHADOWLAB_SEED) once one reports
  merged.hiddenSeed = merged.seed;
  if (const char* env = std::getenv("SHADOWLAB_SEED")) merged.seed = std::strtoull(env, nullptr, 10);
  for (const std::string& a : o.graderArgs)
    if (a.rfind("--seed=", 0) == 0) merged.seed = std::strtoull(a.c_str() + 7, nullptr, 10);
  for (const std::string& id : exercises) {
    const std::vector<CaseResult> cases = gradeExercise(o, id, names, hidden, scratch, merged);
    merged.cases.insert(merged.cases.end(), cases.begin(), cases.end());
  }
  if (!writeReports({o.results, "", "", ""}, {merged}, std::cerr)) return 1;
  std::cout << "grade_isolated: " << exercises.size() << " exercises of " << merged.suite
            << ", each in its own process (limits " << o.timeout << " s, " << o.memoryMb << " MiB): " << o.results
            << "\n";
  return 0;
}

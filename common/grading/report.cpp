#include "grading/report.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "grading/checks.hpp"

namespace shadowlab::grading {
namespace {

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') ? ' ' : c;
    }
  }
  return out;
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

const ExerciseGrade* find(const Grade& g, const std::string& id) {
  for (const auto& e : g.exercises)
    if (e.id == id) return &e;
  return nullptr;
}

// A case's share of its exercise's points.
double share(const Grade& g, const CaseResult& c) {
  const ExerciseGrade* e = find(g, c.exercise);
  return e && e->cases() ? e->maxPoints / e->cases() : 0.0;
}

std::string scoreText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

Grade grade(const std::vector<RunResult>& runs) {
  std::map<std::string, ExerciseGrade> byId;
  Grade g;
  std::map<std::string, double> credit;  // per exercise: cases passed, partial ones by their share
  for (const RunResult& run : runs)
    for (const CaseResult& c : run.cases) {
      ++g.cases;
      g.failures += !c.passed;
      if (c.exercise.empty()) continue;
      ExerciseGrade& e = byId[c.exercise];
      e.id = c.exercise;
      (c.hidden ? (c.passed ? e.hiddenPassed : e.hiddenFailed) : (c.passed ? e.passed : e.failed)) += 1;
      e.stub = e.stub || c.stub;
      credit[c.exercise] += caseCredit(c);
    }
  for (auto& [id, e] : byId) {
    e.points = e.maxPoints * credit[id] / double(std::max(1, e.cases()));
    g.points += e.points;
    g.maxPoints += e.maxPoints;
    g.exercises.push_back(e);
  }
  return g;
}

Json resultsJson(const RunResult& run) {
  Json cases = Json::array();
  for (const CaseResult& c : run.cases)
    cases.push_back({{"name", c.name},
                     {"exercise", c.exercise},
                     {"file", c.file},
                     {"line", c.line},
                     {"passed", c.passed},
                     {"hidden", c.hidden},
                     {"stub", c.stub},
                     {"partial_credit", c.partialCredit},
                     {"checks", c.checks},
                     {"checks_failed", c.checksFailed},
                     {"output", c.output}});
  Json j = {{"suite", run.suite},
            {"seed", run.seed},
            {"hidden_seed", run.hiddenSeed},
            {"test_cases_run", run.testCasesRun},
            {"cases", cases}};
  return j;
}

RunResult runFromJson(const Json& j) {
  RunResult r;
  r.suite = j.at("suite").get<std::string>();
  r.seed = j.at("seed").get<std::uint64_t>();
  r.hiddenSeed = j.value("hidden_seed", r.seed);
  r.testCasesRun = j.value("test_cases_run", 0);
  for (const auto& c : j.at("cases")) {
    CaseResult k;
    k.name = c.at("name").get<std::string>();
    k.exercise = c.at("exercise").get<std::string>();
    k.file = c.value("file", "");
    k.line = c.value("line", 0);
    k.passed = c.at("passed").get<bool>();
    k.hidden = c.value("hidden", false);
    k.stub = c.value("stub", false);
    k.partialCredit = c.value("partial_credit", false);
    k.checks = c.value("checks", 0);
    k.checksFailed = c.value("checks_failed", 0);
    k.output = c.value("output", "");
    r.cases.push_back(std::move(k));
  }
  return r;
}

Json scoreJson(const std::vector<RunResult>& runs, const Grade& g) {
  Json exercises = Json::object();
  int complete = 0;
  for (const ExerciseGrade& e : g.exercises) {
    exercises[e.id] = {{"passed", e.passed},
                       {"failed", e.failed},
                       {"hidden_passed", e.hiddenPassed},
                       {"hidden_failed", e.hiddenFailed},
                       {"score", e.cases() ? double(e.passed + e.hiddenPassed) / e.cases() : 0.0},
                       {"points", e.points},
                       {"max_points", e.maxPoints},
                       {"stub", e.stub}};
    complete += e.cases() > 0 && e.failed + e.hiddenFailed == 0;
  }
  Json seeds = Json::object();
  for (const RunResult& r : runs) {
    seeds[r.suite] = r.seed;
    if (r.hiddenSeed != r.seed) seeds[r.suite + " hidden"] = r.hiddenSeed;
  }
  Json j = {{"score", g.points},
            {"max_score", g.maxPoints},
            {"exercises_complete", complete},
            {"exercises_total", g.exercises.size()},
            {"cases", g.cases},
            {"cases_failed", g.failures},
            {"seeds", seeds},
            {"exercises", exercises}};
  return j;
}

std::string junitXml(const std::vector<RunResult>& runs, const Grade& g) {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += "<testsuites name=\"shadowlab grading\" tests=\"" + std::to_string(g.cases) + "\" failures=\"" +
       std::to_string(g.failures) + "\" errors=\"0\">\n";
  for (const RunResult& run : runs) {
    int failures = 0;
    for (const CaseResult& c : run.cases) failures += !c.passed;
    x += "  <testsuite name=\"" + xmlEscape(run.suite) + "\" tests=\"" + std::to_string(run.cases.size()) +
         "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" skipped=\"0\">\n";
    x += "    <properties>\n      <property name=\"seed\" value=\"" + std::to_string(run.seed) + "\"/>\n";
    x += "      <property name=\"score\" value=\"" + scoreText(g.points) + "\"/>\n";
    x += "      <property name=\"max_score\" value=\"" + scoreText(g.maxPoints) + "\"/>\n    </properties>\n";
    for (const CaseResult& c : run.cases) {
      x += "    <testcase classname=\"" + xmlEscape(c.file) + "\" name=\"" + xmlEscape(c.name) + "\" file=\"" +
           xmlEscape(c.file) + "\" line=\"" + std::to_string(c.line) + "\"";
      if (c.passed) {
        x += "/>\n";
        continue;
      }
      x += ">\n      <failure message=\"" + xmlEscape(firstLine(c.output)) + "\">" + xmlEscape(c.output) +
           "</failure>\n    </testcase>\n";
    }
    x += "  </testsuite>\n";
  }
  return x + "</testsuites>\n";
}

Json gradescopeJson(const std::vector<RunResult>& runs, const Grade& g) {
  Json tests = Json::array();
  for (const RunResult& run : runs)
    for (const CaseResult& c : run.cases) {
      if (c.exercise.empty()) continue;
      const double max = share(g, c);
      std::string output = c.passed ? "passed" : c.output;
      if (c.stub) output += "\n(the exercise's SHADOWLAB_STUB marker is still in place)";
      tests.push_back({{"name", c.name},
                       {"number", c.exercise},
                       {"score", max * caseCredit(c)},
                       {"max_score", max},
                       {"status", c.passed ? "passed" : "failed"},
                       {"output", output},
                       {"visibility", c.hidden ? "after_published" : "visible"},
                       {"tags", {run.suite}}});
    }
  // What a student sees before publication: the visible cases only. Points and hidden cases
  // (which share an exercise's points) would let resubmissions probe the hidden ones.
  std::string summary;
  for (const ExerciseGrade& e : g.exercises)
    summary += "exercise " + e.id + ": " + std::to_string(e.passed) + " of " + std::to_string(e.passed + e.failed) +
               " visible cases passed" + (e.stub ? ", still a stub" : "") + "\n";
  if (std::any_of(g.exercises.begin(), g.exercises.end(),
                  [](const ExerciseGrade& e) { return e.hiddenPassed + e.hiddenFailed > 0; }))
    summary += "Hidden cases are graded too; they and the points appear when the grades are published.\n";
  for (const RunResult& run : runs)
    summary += run.suite + ": seed " + std::to_string(run.seed) +
               (run.hiddenSeed != run.seed ? " (hidden cases: their own seed)" : "") + "\n";
  Json j = {{"score", g.points},
            {"output", summary},
            {"visibility", "visible"},
            {"stdout_visibility", "hidden"},
            {"tests", tests}};
  return j;
}

bool writeFile(const std::string& path, const std::string& text) {
  const std::filesystem::path p(path);
  std::error_code ec;
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  return bool(out);
}

}  // namespace shadowlab::grading

namespace shadowlab::grading {

Json resultsJson(const std::vector<RunResult>& runs) {
  Json all = Json::array();
  for (const RunResult& r : runs) all.push_back(resultsJson(r));
  return Json{{"runs", all}};
}

std::vector<RunResult> runsFromJson(const Json& j) {
  std::vector<RunResult> runs;
  for (const auto& r : j.at("runs")) runs.push_back(runFromJson(r));
  return runs;
}

bool writeReports(const ReportFiles& files, const std::vector<RunResult>& runs, std::ostream& err) {
  const Grade g = grade(runs);
  const std::pair<const std::string*, std::string> texts[] = {
      {&files.results, resultsJson(runs).dump(2) + "\n"},
      {&files.score, scoreJson(runs, g).dump(2) + "\n"},
      {&files.junit, junitXml(runs, g)},
      {&files.gradescope, gradescopeJson(runs, g).dump(2) + "\n"}};
  for (const auto& [path, text] : texts) {
    if (path->empty() || writeFile(*path, text)) continue;
    err << "cannot write " << *path << "\n";
    return false;
  }
  return true;
}

bool stubsScoreZero(const std::vector<RunResult>& runs, std::ostream& out, std::ostream& err) {
  const Grade g = grade(runs);
  if (g.exercises.empty()) {
    err << "validity: no exercise cases (named \"exNN.k: ...\") ran\n";
    return false;
  }
  int bad = 0;
  for (const RunResult& run : runs)
    for (const CaseResult& c : run.cases)
      if (!c.exercise.empty() && c.passed) {
        err << "validity: \"" << c.name << "\" PASSES on the untouched stub: the stub would earn points\n";
        ++bad;
      }
  for (const ExerciseGrade& e : g.exercises)
    if (e.points == 0)
      out << "validity: " << e.id << " scores 0 on the stub, as it must (" << e.cases() << " cases fail)\n";
  return bad == 0;
}

bool renderInformative(const nlohmann::json& j, std::string& why) {
  if (!j.is_object()) return why = "no ground-truth figures", false;
  auto number = [](const nlohmann::json& o, const char* key) {
    return o.is_object() && o.contains(key) && o[key].is_number() ? o[key].get<double>() : 0.0;
  };
  const double pixels = std::max(number(j, "width") * number(j, "height"), 1.0);
  auto share = [&](double n) { return show(100 * n / pixels) + "%"; };
  if (j.contains("hard")) {
    const double facing = number(j["hard"], "facing_pixels"), shadowed = number(j["hard"], "reference_shadowed");
    why = share(shadowed) + " of the view in shadow, " + share(facing - shadowed) + " lit";
    return shadowed >= 0.02 * pixels && facing - shadowed >= 0.02 * pixels;
  }
  if (j.contains("soft")) {
    const double seen = number(j["soft"], "pixels"), umbra = number(j["soft"], "umbra_pixels");
    why = share(umbra) + " of the view umbra, " + share(seen - umbra) + " penumbra or lit";
    return umbra >= 0.005 * pixels && seen - umbra >= 0.02 * pixels;
  }
  return why = "no hard or soft shadow figures", false;
}

}  // namespace shadowlab::grading

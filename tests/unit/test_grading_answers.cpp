// The grader's trust boundary (grading/answers.hpp): what the student's process records is what the
// judging process replays, value for value, exception for exception, stub marker for stub marker;
// a missing, reordered or damaged answer fails the call that asked, never passes it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "grading/answers.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace answers_test {
float half(float x) { return x / 2; }
glm::mat4 scaled(const glm::vec3& s) {
  return glm::mat4(glm::vec4(s.x, 0, 0, 0), glm::vec4(0, s.y, 0, 0), glm::vec4(0, 0, s.z, 0), glm::vec4(0, 0, 0, 1));
}
std::vector<double> ramp(int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(0.5 * i);
  return v;
}
float picky(float x) {
  if (x < 0) throw std::invalid_argument("x < 0: " + std::to_string(x));
  SHADOWLAB_STUB("99.1");
  return 1.0f;
}
inline constexpr grading::Graded<&half, decltype(&half)> gHalf{"answers_test::half"};
inline constexpr grading::Graded<&scaled, decltype(&scaled)> gScaled{"answers_test::scaled"};
inline constexpr grading::Graded<&ramp, decltype(&ramp)> gRamp{"answers_test::ramp"};
inline constexpr grading::Graded<&picky, decltype(&picky)> gPicky{"answers_test::picky"};
}  // namespace answers_test

namespace {
std::string answersFile(const char* name) {
  const auto dir = std::filesystem::temp_directory_path() / "shadowlab_answers_test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
struct BackToDirect {
  ~BackToDirect() { grading::useDirectAnswers(); }
};
}  // namespace

TEST_CASE("answers: recorded values, exceptions and stub markers replay exactly, braced arguments included") {
  using namespace answers_test;
  BackToDirect restore;
  const std::string path = answersFile("round_trip.bin");
  grading::clearStubsReached();
  grading::recordAnswersTo(path);
  CHECK(gHalf(3.0f) == 1.5f);
  CHECK(gScaled({2, 3, 4})[1][1] == 3.0f);
  CHECK(gRamp(4).size() == 4);
  CHECK_THROWS_AS(gPicky(-1.0f), std::invalid_argument);
  CHECK(gPicky(1.0f) == 1.0f);
  std::string error;
  REQUIRE(grading::writeRecordedAnswers(error));

  grading::clearStubsReached();
  REQUIRE(grading::replayAnswersFrom(path, error));
  CHECK(grading::answerMode() == grading::AnswerMode::kReplay);
  // The replaying process would compute other values: the recorded ones come back instead.
  CHECK(gHalf(100.0f) == 1.5f);
  const glm::mat4 m = gScaled({9, 9, 9});
  CHECK(m[0][0] == 2.0f);
  CHECK(m[2][2] == 4.0f);
  CHECK(gRamp(0) == std::vector<double>{0.0, 0.5, 1.0, 1.5});
  CHECK(grading::stubsReached().empty());
  CHECK_THROWS_WITH_AS(gPicky(5.0f), "x < 0: -1.000000", std::invalid_argument);
  CHECK(gPicky(-7.0f) == 1.0f);
  CHECK(grading::stubsReached() == std::set<std::string>{"99.1"});
  // No answer left: the call fails, naming itself.
  CHECK_THROWS_WITH_AS(gHalf(1.0f), doctest::Contains("no answer from your code for this call of answers_test::half"),
                       std::runtime_error);
  grading::clearStubsReached();
}

TEST_CASE("answers: an answer out of order or damaged fails, never passes") {
  using namespace answers_test;
  BackToDirect restore;
  const std::string path = answersFile("order.bin");
  grading::recordAnswersTo(path);
  gHalf(2.0f);
  std::string error;
  REQUIRE(grading::writeRecordedAnswers(error));
  REQUIRE(grading::replayAnswersFrom(path, error));
  CHECK_THROWS_WITH_AS(gRamp(1), doctest::Contains("the answers do not follow the grader's calls"), std::runtime_error);

  // A truncated file, a foreign file, no file: refused with the path and why.
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 2);
  CHECK_FALSE(grading::replayAnswersFrom(path, error));
  CHECK(error.find("answer 1 is truncated") != std::string::npos);
  std::ofstream(path, std::ios::trunc) << "{\"passed\": true}";
  CHECK_FALSE(grading::replayAnswersFrom(path, error));
  CHECK(error == path + " is not an answers file");
  CHECK_FALSE(grading::replayAnswersFrom(path + ".missing", error));
  CHECK(error == "no answers file " + path + ".missing");

  // A value of the wrong size (a forged file) is refused, not read past.
  grading::recordAnswersTo(path);
  grading::recordAnswer({"answers_test::half", {}, 0, "", "ab"});
  REQUIRE(grading::writeRecordedAnswers(error));
  REQUIRE(grading::replayAnswersFrom(path, error));
  CHECK_THROWS_WITH_AS(gHalf(1.0f), "the recorded answer is shorter than its type", std::runtime_error);
}

TEST_CASE("answers: a length field longer than the file is refused before anything is allocated") {
  // The fuzzer's find: a call name claiming 1.9 GB in a 150-byte file took 2 GB of memory first.
  std::string bytes = grading::serializeAnswers({{"answers_test::half", {}, 0, "", "abcd"}});
  const std::size_t lengthAt = std::string("shadowlab answers 1\n").size();
  const std::uint64_t huge = std::uint64_t(0x7b005911);
  bytes.replace(lengthAt, sizeof huge, reinterpret_cast<const char*>(&huge), sizeof huge);
  std::vector<grading::Answer> answers;
  std::string error;
  CHECK_FALSE(grading::parseAnswers(bytes, answers, error));
  CHECK(error == "answer 1 is truncated");
  // One byte past the end is as wrong as a gigabyte: the value's length says 5, four bytes follow.
  bytes = grading::serializeAnswers({{"answers_test::half", {}, 0, "", "abcd"}});
  bytes[bytes.size() - 4 - 8] = 5;
  CHECK_FALSE(grading::parseAnswers(bytes, answers, error));
  CHECK(error == "answer 1 is truncated");
}

TEST_CASE("answers: without record or replay a proxy calls the function") {
  using namespace answers_test;
  grading::useDirectAnswers();
  CHECK(grading::answerMode() == grading::AnswerMode::kDirect);
  CHECK(gHalf(8.0f) == 4.0f);
  CHECK_THROWS_AS(gPicky(-2.0f), std::invalid_argument);
}

#include "grading/report.hpp"

TEST_CASE("gradescope: the visible summary counts visible cases only, never a hidden one or points") {
  grading::RunResult run;
  run.suite = "grade_ex01";
  auto add = [&](const char* name, bool passed, bool hidden) {
    grading::CaseResult c;
    c.name = name;
    c.exercise = grading::exerciseOf(name);
    c.passed = passed;
    c.hidden = hidden;
    c.output = passed ? "" : "SECRET inputs of this case";
    run.cases.push_back(c);
  };
  add("ex01.1: a", true, false);
  add("ex01.1: b", false, false);
  add("ex01.1: hidden one", false, true);
  add("ex01.1: hidden two", true, true);
  const std::vector<grading::RunResult> runs = {run};
  const grading::Json j = grading::gradescopeJson(runs, grading::grade(runs));
  const std::string summary = j.at("output").get<std::string>();
  CHECK(summary.find("exercise 01.1: 1 of 2 visible cases passed\n") != std::string::npos);
  CHECK(summary.find("Hidden cases are graded too") != std::string::npos);
  CHECK(summary.find("points (") == std::string::npos);  // no score per exercise: it holds the hidden cases
  CHECK(summary.find("of 4") == std::string::npos);
  for (const auto& t : j.at("tests"))
    if (t.at("name").get<std::string>().find("hidden") != std::string::npos)
      CHECK(t.at("visibility") == "after_published");
}

TEST_CASE("scores: a case of independent checks earns the share that held; others, stubs and throws all or nothing") {
  auto make = [](const char* name, bool passed, bool partial, int checks, int failed, bool stub = false) {
    grading::CaseResult c;
    c.name = name;
    c.exercise = grading::exerciseOf(name);
    c.passed = passed;
    c.partialCredit = partial;
    c.checks = checks;
    c.checksFailed = failed;
    c.stub = stub;
    return c;
  };
  grading::RunResult run;
  run.cases = {make("ex03.1: by hand", false, true, 6, 2),        // 4 of 6 held: 2/3 of its share
               make("ex03.1: random", true, false, 200, 0),       // passed: its whole share
               make("ex03.2: by hand", false, false, 3, 1),       // not marked independent: nothing
               make("ex03.2: random", false, true, 3, 1, true)};  // a stub earns nothing, marked or not
  const grading::Grade g = grading::grade({run});
  REQUIRE(g.exercises.size() == 2);
  CHECK(g.exercises[0].points == doctest::Approx(10.0 * (2.0 / 3.0 + 1.0) / 2.0));
  CHECK(g.exercises[1].points == 0.0);
  CHECK(grading::caseCredit(run.cases[0]) == doctest::Approx(2.0 / 3.0));
  // The results file keeps what the score needs, so grade_report scores the same.
  const grading::RunResult back = grading::runFromJson(grading::resultsJson(run));
  CHECK(grading::grade({back}).points == doctest::Approx(g.points));
  const grading::Json gs = grading::gradescopeJson({run}, g);
  CHECK(gs.at("tests")[0].at("score").get<double>() == doctest::Approx(5.0 * 2.0 / 3.0));
}

// Recorded camera and light paths: interpolation, round trips, and errors that name file and line.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "measure/paths.hpp"

using namespace shadowlab::measure;

namespace {

CameraLightPath twoKeys() {
  CameraLightPath path;
  PathKey a;
  a.time = 1.0;
  a.cameraPosition = {0, 2, 8};
  a.cameraTarget = {0, 0, 0};
  a.lightPosition = {0, 8, 0};
  a.lightDirection = {1, 0, 0};
  PathKey b = a;
  b.time = 3.0;
  b.cameraPosition = {4, 2, 0};
  b.cameraTarget = {2, 0, -2};
  b.lightPosition = {0, 4, 0};
  b.lightDirection = {0, 0, 5};  // normalised on add
  path.add(a);
  path.add(b);
  return path;
}

}  // namespace

TEST_CASE("measure.paths: replay interpolates positions linearly and directions along the arc") {
  CameraLightPath path = twoKeys();
  CHECK(path.duration() == 2.0);
  PathKey mid = path.sample(2.0);
  CHECK(mid.cameraPosition.x == doctest::Approx(2));
  CHECK(mid.cameraPosition.z == doctest::Approx(4));
  CHECK(mid.cameraTarget.z == doctest::Approx(-1));
  CHECK(mid.lightPosition.y == doctest::Approx(6));
  // Halfway between +x and +z on the unit circle: (1, 0, 1) / sqrt 2, still unit length.
  CHECK(mid.lightDirection.x == doctest::Approx(std::sqrt(0.5)));
  CHECK(mid.lightDirection.z == doctest::Approx(std::sqrt(0.5)));
  CHECK(glm::length(path.sample(1.5).lightDirection) == doctest::Approx(1.0));
  // Clamped outside, with the asked time reported.
  CHECK(path.sample(0.0).cameraPosition == path.keys()[0].cameraPosition);
  CHECK(path.sample(9.0).cameraPosition == path.keys()[1].cameraPosition);
  CHECK(path.sample(9.0).time == 9.0);
  std::vector<PathKey> frames = path.resample(5);
  REQUIRE(frames.size() == 5);
  CHECK(frames[0].time == 1.0);
  CHECK(frames[4].time == 3.0);
  CHECK(frames[2].cameraPosition.x == doctest::Approx(2));
  CHECK_THROWS_AS(CameraLightPath().sample(0), std::logic_error);
}

TEST_CASE("measure.paths: keys must move forward in time and light directions must exist") {
  CameraLightPath path = twoKeys();
  PathKey early;
  early.time = 3.0;
  CHECK_THROWS_WITH_AS(path.add(early), doctest::Contains("3.0"), std::invalid_argument);
  PathKey dark;
  dark.time = 5.0;
  dark.lightDirection = {0, 0, 0};
  CHECK_THROWS_AS(path.add(dark), std::invalid_argument);
}

TEST_CASE("measure.paths: save and load round-trip every key") {
  CameraLightPath path = twoKeys();
  PathKey odd;
  odd.time = 3.125;
  odd.cameraPosition = {0.1f, -1e-3f, 12345.678f};
  odd.lightDirection = glm::normalize(glm::vec3(0.3f, -0.7f, 0.2f));
  path.add(odd);
  auto file = std::filesystem::temp_directory_path() / "shadowlab_measure_path_roundtrip.txt";
  path.save(file.string());
  CameraLightPath loaded = CameraLightPath::load(file.string());
  std::filesystem::remove(file);
  REQUIRE(loaded.keys().size() == 3);
  for (std::size_t i = 0; i < 3; ++i) CHECK(loaded.keys()[i] == path.keys()[i]);
  CHECK_THROWS_WITH_AS(CameraLightPath::load("/nonexistent/dir/p.txt"), doctest::Contains("/nonexistent/dir/p.txt"),
                       std::runtime_error);
}

TEST_CASE("measure.paths: bad lines are reported with file name and line number") {
  auto errorOf = [](const std::string& text) {
    std::istringstream in(text);
    try {
      CameraLightPath::read(in, "walk.path");
    } catch (const std::runtime_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  const std::string head = "shadowlab-path 1\n# comment\n\n";
  const std::string good = "key 0  0 2 8  0 0 0  0 8 0  0 -1 0\n";
  CHECK(errorOf(head + good) == "no error");
  CHECK(errorOf(head + good + "key 1  0 2 8  0 0 0  0 8 0  0 -1\n").rfind("walk.path:5: key has 12 numbers", 0) == 0);
  CHECK(errorOf(head + good + "key 1  0 2 8  0 0 zero  0 8 0  0 -1 0\n").rfind("walk.path:5: 'zero'", 0) == 0);
  CHECK(errorOf(head + good + "key 1  0 2 8  0 0 0  0 8 0  0 -1 0 7\n").rfind("walk.path:5: unexpected '7'", 0) == 0);
  CHECK(errorOf(head + good + "key 0  0 2 8  0 0 0  0 8 0  0 -1 0\n").rfind("walk.path:5: ", 0) == 0);  // time
  CHECK(errorOf(head + good + "key 1  0 2 8  0 0 0  0 8 0  0 0 0\n").rfind("walk.path:5: ", 0) == 0);   // no dir
  CHECK(errorOf(head + "camera 1 2 3\n").rfind("walk.path:4: unknown record 'camera'", 0) == 0);
  CHECK(errorOf("key 0 0 0 0 0 0 0 0 0 0 0 -1 0\n").rfind("walk.path:1: expected 'shadowlab-path 1'", 0) == 0);
  CHECK(errorOf("shadowlab-path 2\n").rfind("walk.path:1: unsupported path version '2'", 0) == 0);
  CHECK(errorOf("").rfind("walk.path:1: empty file", 0) == 0);
  CHECK(errorOf(head + "key 1 nan 2 8 0 0 0 0 8 0 0 -1 0\n").rfind("walk.path:4: 'nan'", 0) == 0);
}

TEST_CASE("measure.paths: the fuzzing finds are refused naming file:line (they crashed or rendered nothing)") {
  auto errorOf = [](const std::string& text) {
    std::istringstream in(text);
    try {
      CameraLightPath::read(in, "e.path");
    } catch (const std::runtime_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  const std::string head = "shadowlab-path 1\n";
  // The eye at its target: OrbitCamera::lookFrom threw out of every lesson (exit 134).
  CHECK(errorOf(head + "key 0 0 0 0 0 0 0 0 8 0 0 -1 0\n") ==
        "e.path:2: the camera at (0, 0, 0) is at its target (0, 0, 0): a view needs a direction");
  // 1e300 became inf in a float: a blank frame and exit 0.
  CHECK(errorOf(head + "key 0 1e300 2 8 0 0 0 0 8 0 0 -1 0\n") ==
        "e.path:2: camera position (1e+300, 2, 8) is outside +-1000000");
  CHECK(errorOf(head + "key 0 0 2 8 0 0 0 0 8 1e7 0 -1 0\n") ==
        "e.path:2: light position (0, 8, 1e+07) is outside +-1000000");
  // Headers: only exactly "shadowlab-path 1".
  CHECK(errorOf("shadowlab-path 1.5\n") == "e.path:1: unsupported path version '1.5' (this reads version 1)");
  CHECK(errorOf("shadowlab-path 1 junk\n") == "e.path:1: expected 'shadowlab-path 1', got 'shadowlab-path 1 junk'");
  CHECK(errorOf("shadowlab-path\n") == "e.path:1: expected 'shadowlab-path 1', got 'shadowlab-path'");
  // Numbers: decimal and finite, nothing else.
  for (const char* bad : {"inf", "-inf", "nan", "1e999", "0x10", "+1", "1,5", "--1"}) {
    INFO(bad);
    CHECK(errorOf(head + "key " + bad + " 0 2 8 0 0 0 0 8 0 0 -1 0\n") ==
          "e.path:2: '" + std::string(bad) + "' is not a finite number (field 1)");
  }
  CHECK(errorOf(head + "key 0 0 2 8 0 0 0 0 8 0 0 0 0\n") == "e.path:2: light direction (0, 0, 0) is not a direction");
  // Two valid keys whose interpolation puts the eye on the target halfway: refused at load too.
  CHECK(errorOf(head + "key 0 0 0 0 1 0 0 0 8 0 0 -1 0\nkey 1 1 0 0 0 0 0 0 8 0 0 -1 0\n") ==
        "e.path:3: between the previous key and this one the camera passes through its target (at 50 % of the way)");
}

TEST_CASE("measure.paths: huge and tiny light directions normalise (in float, 1e20 gave 0 and 1e-30 NaN)") {
  for (const char* direction : {"1e20 0 0", "1e300 0 0", "1e-30 0 0", "1e-300 0 0", "3e38 3e38 0"}) {
    INFO(direction);
    std::istringstream in("shadowlab-path 1\nkey 0 0 2 8 0 0 0 0 8 0 " + std::string(direction) + "\n");
    const CameraLightPath path = CameraLightPath::read(in, "d.path");
    const glm::vec3 d = path.keys()[0].lightDirection;
    CHECK(glm::length(d) == doctest::Approx(1.0));
    CHECK(d.x > 0.7f);
  }
  PathKey k;
  k.lightDirection = {1e-30f, 0, 0};  // add() on floats as well: what a recording passes
  CameraLightPath path;
  path.add(k);
  CHECK(path.keys()[0].lightDirection == glm::vec3(1, 0, 0));
  k.time = 1;
  k.cameraTarget = k.cameraPosition;
  CHECK_THROWS_WITH_AS(path.add(k), doctest::Contains("is at its target"), std::invalid_argument);
}

TEST_CASE("measure.paths: --replay FILE@T and FILE@T0..T1: the time after the last '@', a file with '@' stays whole") {
  CHECK(parseReplaySpec("walk.path").file == "walk.path");
  CHECK(parseReplaySpec("walk.path").holdAt == -1.0);
  const ReplaySpec held = parseReplaySpec("runs@2/walk.path@1.5");
  CHECK(held.file == "runs@2/walk.path");
  CHECK(held.holdAt == 1.5);
  CHECK(parseReplaySpec("walk.path@0").holdAt == 0.0);
  for (const char* bad : {"walk.path@inf", "walk.path@nan", "walk.path@-1", "walk.path@", "walk.path@1s", "a@b"}) {
    INFO(bad);
    CHECK_THROWS_WITH_AS(parseReplaySpec(bad), doctest::Contains("after '@' is not a time >= 0"),
                         std::invalid_argument);
  }
  // A span: the frames play from T0 to T1; a window plays it in real time and stops at T1.
  const ReplaySpec span = parseReplaySpec("walk.path@0.5..0.75");
  CHECK(span.file == "walk.path");
  CHECK(span.holdAt == -1.0);
  CHECK(span.timeAt(2.0, 0, 3, 0.0) == 0.5);
  CHECK(span.timeAt(2.0, 1, 3, 0.0) == doctest::Approx(0.625));
  CHECK(span.timeAt(2.0, 2, 3, 0.0) == 0.75);
  CHECK(span.timeAt(2.0, 0, 0, 0.1) == doctest::Approx(0.6));
  CHECK(span.timeAt(2.0, 0, 0, 9.0) == 0.75);
  CHECK(parseReplaySpec("walk.path").timeAt(2.0, 4, 5, 0.0) == 2.0);  // the whole path over the frames
  CHECK(parseReplaySpec("walk.path").timeAt(2.0, 0, 0, 1.5) == 1.5);
  CHECK(held.timeAt(2.0, 4, 5, 3.0) == 1.5);
  for (const char* bad : {"walk.path@1..0.5", "walk.path@1..1", "walk.path@-1..2", "walk.path@0..inf", "walk.path@..2",
                          "walk.path@0..", "walk.path@0..1..2"}) {
    INFO(bad);
    CHECK_THROWS_WITH_AS(parseReplaySpec(bad), doctest::Contains("is not a span T0..T1"), std::invalid_argument);
  }
  // An existing file whose name has an '@' (and what follows is no time) is that file.
  const auto dir = std::filesystem::temp_directory_path() / "shadowlab_replay@take2";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "walk.path@final").string();
  { std::ofstream(file) << "shadowlab-path 1\n"; }
  CHECK(parseReplaySpec(file).file == file);
  CHECK(parseReplaySpec(file).holdAt == -1.0);
  CHECK(parseReplaySpec(file + "@2").file == file);
  std::filesystem::remove_all(dir);
}

// Recorded camera and light paths: interpolation, round trips, and errors that name file and line.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
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
  CHECK(errorOf("shadowlab-path 2\n").rfind("walk.path:1: unsupported path version 2", 0) == 0);
  CHECK(errorOf("").rfind("walk.path:1: empty file", 0) == 0);
  CHECK(errorOf(head + "key 1 nan 2 8 0 0 0 0 8 0 0 -1 0\n").rfind("walk.path:4: 'nan'", 0) == 0);
}

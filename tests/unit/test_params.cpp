#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/params.hpp"

using namespace shadowlab;

namespace {
enum class Mode { Lit, Normals, Depth };
struct Params {
  float ambient = 0.1f;
  int samples = 4;
  bool shadows = true;
  Mode mode = Mode::Lit;
  glm::vec3 color{1, 0.5f, 0};
};
struct Fixture {
  Params p;
  ParamRegistry reg;
  Fixture() {
    reg.add("ambient", &p.ambient, 0, 1, "k_a");
    reg.add("samples", &p.samples, 1, 64, "PCF taps");
    reg.add("shadows", &p.shadows, "V_i on/off");
    reg.addChoice("mode", &p.mode, {"lit", "normals", "depth"}, "what to show");
    reg.addColor("color", &p.color, "light colour");
  }
};
std::string tempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("shadowlab_test_") + name)).string();
}
}  // namespace

TEST_CASE("params: set and get every kind in text form") {
  Fixture f;
  f.reg.set("ambient", "0.25");
  f.reg.set("samples", "16");
  f.reg.set("shadows", "off");
  f.reg.set("mode", "depth");
  f.reg.assign("color=0 1 0.5");
  CHECK(f.p.ambient == doctest::Approx(0.25f));
  CHECK(f.p.samples == 16);
  CHECK_FALSE(f.p.shadows);
  CHECK(f.p.mode == Mode::Depth);
  CHECK(f.p.color == glm::vec3(0, 1, 0.5f));
  CHECK(f.reg.get("mode") == "depth");
  CHECK(f.reg.get("shadows") == "false");
  CHECK(f.reg.get("color") == "0 1 0.5");
}

TEST_CASE("params: bad input names the value and the valid choices, and changes nothing") {
  Fixture f;
  auto message = [&](const std::string& name, const std::string& value) {
    try {
      f.reg.set(name, value);
    } catch (const ParamError& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  CHECK(message("ambient", "2") == "bad value '2' for ambient (float); valid: [0, 1]");
  CHECK(message("ambient", "abc").find("bad value 'abc'") == 0);
  CHECK(message("samples", "1.5") == "bad value '1.5' for samples (int); valid: [1, 64]");
  CHECK(message("mode", "wire") == "bad value 'wire' for mode (choice); valid: lit, normals, depth");
  CHECK(message("shadows", "maybe").find("valid: true, false") != std::string::npos);
  CHECK(message("color", "1 2").find("three numbers") != std::string::npos);
  CHECK(message("nope", "1") == "unknown parameter 'nope'; valid: ambient, samples, shadows, mode, color");
  CHECK(f.p.ambient == doctest::Approx(0.1f));
  CHECK(f.p.samples == 4);
  CHECK(f.p.mode == Mode::Lit);
  CHECK_THROWS_AS(f.reg.assign("ambient"), ParamError);
  CHECK_THROWS_AS(f.reg.set("ambient", "nan"), ParamError);
}

TEST_CASE("params: defaults, reset, revision and registration errors") {
  Fixture f;
  const unsigned r0 = f.reg.revision();
  f.reg.set("samples", "8");
  CHECK(f.reg.revision() == r0 + 1);
  f.reg.resetDefaults();
  CHECK(f.p.samples == 4);
  CHECK(f.reg.find("samples")->defaultValue == "4");
  float other = 0;
  CHECK_THROWS_AS(f.reg.add("ambient", &other, 0, 1, "dup"), ParamError);
  CHECK_THROWS_AS(f.reg.add("Bad Name", &other, 0, 1, "x"), ParamError);
  CHECK(f.reg.describe().find("samples") != std::string::npos);
}

TEST_CASE("presets: load, validate, apply over defaults, capture and save round trip") {
  Fixture f;
  const std::string path = tempPath("presets.txt");
  {
    std::ofstream out(path);
    out << "# comment\n[dark]\nambient = 0\nmode = normals\n\n[many_samples]\nsamples = 64\n";
  }
  PresetFile file = PresetFile::load(path);
  REQUIRE(file.names() == std::vector<std::string>{"dark", "many_samples"});
  file.validate(f.reg);
  f.reg.set("samples", "2");
  file.apply("dark", f.reg);
  CHECK(f.p.ambient == 0.0f);
  CHECK(f.p.mode == Mode::Normals);
  CHECK(f.p.samples == 4);  // not in the preset: back to its default
  f.reg.set("shadows", "false");
  file.capture("dark_noshadow", f.reg);
  file.save(path);
  PresetFile again = PresetFile::load(path);
  REQUIRE(again.find("dark_noshadow"));
  again.apply("dark_noshadow", f.reg);
  CHECK_FALSE(f.p.shadows);
  CHECK(f.p.mode == Mode::Normals);
  try {
    again.apply("bright", f.reg);
    FAIL("unknown preset accepted");
  } catch (const ParamError& e) {
    CHECK(std::string(e.what()).find("valid: dark, many_samples, dark_noshadow") != std::string::npos);
  }
  std::remove(path.c_str());
}

TEST_CASE("presets: malformed files name the file and the line") {
  Fixture f;
  const std::string path = tempPath("bad.txt");
  auto errorOf = [&](const std::string& text, bool validate) {
    { std::ofstream(path) << text; }
    try {
      PresetFile file = PresetFile::load(path);
      if (validate) file.validate(f.reg);
    } catch (const ParamError& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  CHECK(errorOf("[a]\nambient 0.5\n", false) == path + ":2: expected 'name = value' or [preset], got 'ambient 0.5'");
  CHECK(errorOf("ambient = 1\n", false).rfind(path + ":1: ", 0) == 0);
  CHECK(errorOf("[a\n", false).rfind(path + ":1: ", 0) == 0);
  CHECK(errorOf("[a]\n[a]\n", false) == path + ":2: preset 'a' is defined twice");
  CHECK(
      errorOf("[a]\nambient = 0.5\nwhat = 1\n", true).rfind(path + ":3: in preset 'a': unknown parameter 'what'", 0) ==
      0);
  CHECK(f.p.ambient == doctest::Approx(0.1f));  // validation leaves values alone
  std::remove(path.c_str());
}

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/params.hpp"
#include "sample_params.hpp"

using namespace shadowlab;
using test::Mode;

namespace {
struct Fixture {
  test::SampleParams p;
  ParamRegistry reg;
  Fixture() { p.declare(reg); }
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

TEST_CASE("params: changed() lists what differs from the defaults, and assigning it rebuilds the state") {
  Fixture f;
  CHECK(f.reg.changed().empty());
  f.reg.set("samples", "16");
  f.reg.assign("color=0 1 0.5");
  f.reg.set("ambient", f.reg.find("ambient")->defaultValue);  // set, but to its default: not listed
  const ParamValues changed = f.reg.changed();
  REQUIRE(changed.size() == 2);
  CHECK(changed[0].first + "=" + changed[0].second == "samples=16");  // registration order
  CHECK(changed[1].first + "=" + changed[1].second == "color=0 1 0.5");
  Fixture fresh;  // what a copied link does on a new page
  std::vector<std::string> assignments;
  for (const auto& [name, value] : changed) assignments.push_back(name + "=" + value);
  fresh.reg.assignAll(assignments);
  CHECK(fresh.reg.snapshot() == f.reg.snapshot());
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
  CHECK(errorOf("[a]\n[a]\n", false) == path + ":2: preset 'a' is defined twice (first on line 1)");
  CHECK(
      errorOf("[a]\nambient = 0.5\nwhat = 1\n", true).rfind(path + ":3: in preset 'a': unknown parameter 'what'", 0) ==
      0);
  CHECK(f.p.ambient == doctest::Approx(0.1f));  // validation leaves values alone
  std::remove(path.c_str());
}

TEST_CASE("presets: errors name the value's own line, whatever comments and blank lines lie between") {
  Fixture f;
  const std::string path = tempPath("lines.txt");
  { std::ofstream(path) << "[a]\n# a comment\n\nambient = 0.5\n   \n# another\nsamples = 999\n[b]\nmode = lit\n"; }
  const PresetFile file = PresetFile::load(path);
  REQUIRE(file.presets.size() == 2);
  CHECK(file.presets[0].values[0].line == 4);
  CHECK(file.presets[0].values[1].line == 7);
  CHECK(file.presets[1].values[0].line == 9);
  try {
    file.validate(f.reg);
    FAIL("an out-of-range preset value was accepted");
  } catch (const ParamError& e) {
    CHECK(std::string(e.what()) == path + ":7: in preset 'a': bad value '999' for samples (int); valid: [1, 64]");
  }
  try {
    file.apply("a", f.reg);
    FAIL("an out-of-range preset value was applied");
  } catch (const ParamError& e) { CHECK(std::string(e.what()).rfind(path + ":7: in preset 'a': ", 0) == 0); }
  CHECK(f.p.ambient == doctest::Approx(0.1f));  // a refused preset changes nothing
  std::remove(path.c_str());
}

TEST_CASE("presets: 100,000 presets load and validate (duplicates are found without a quadratic scan)") {
  Fixture f;
  const std::string path = tempPath("many.txt");
  {
    std::ofstream out(path);
    for (int i = 0; i < 100000; ++i) out << "[p" << i << "]\nsamples = " << 1 + i % 64 << "\n";
    out << "[p77]\n";
  }
  try {
    PresetFile::load(path);
    FAIL("a duplicate preset was accepted");
  } catch (const ParamError& e) {
    CHECK(std::string(e.what()) == path + ":200001: preset 'p77' is defined twice (first on line 155)");
  }
  {
    std::ofstream out(path);
    for (int i = 0; i < 100000; ++i) out << "[p" << i << "]\nsamples = " << 1 + i % 64 << "\n";
  }
  const PresetFile file = PresetFile::load(path);
  CHECK(file.presets.size() == 100000);
  file.validate(f.reg);
  file.apply("p99999", f.reg);
  CHECK(f.p.samples == 1 + 99999 % 64);
  std::remove(path.c_str());
}

namespace {
// Two values that are each in range but together degenerate: lo must stay below hi.
struct Pair {
  float lo = 1, hi = 2;
  ParamRegistry reg;
  Pair() {
    reg.add("lo", &lo, 0, 10, "lower");
    reg.add("hi", &hi, 0, 10, "upper");
    reg.addCheck({"lo", "hi"}, [this](const ParamRegistry& r) {
      return lo < hi ? std::string() : "lo = " + r.get("lo") + " is not below hi = " + r.get("hi");
    });
  }
  std::string error(const std::function<void()>& change) {
    try {
      change();
    } catch (const ParamError& e) { return e.what(); }
    return "no error";
  }
};
}  // namespace

TEST_CASE("params: a check refuses a change, names the values, and keeps the last good value exactly") {
  Pair p;
  p.reg.set("lo", "0.1");
  p.reg.set("hi", "0.30000001");
  const float good = p.hi;
  const unsigned revision = p.reg.revision();
  CHECK(p.error([&] { p.reg.set("lo", "5"); }) == "lo = 5 is not below hi = 0.3");
  CHECK(p.lo == 0.1f);
  CHECK(p.error([&] { p.reg.set("hi", "0.05"); }) == "lo = 0.1 is not below hi = 0.05");
  CHECK(p.hi == good);                  // restored bit for bit, not through the six-digit text form
  CHECK(p.reg.revision() == revision);  // a refused change is no change
  CHECK_NOTHROW(p.reg.validate());
  p.reg.set("lo", "0.2");
  CHECK(p.reg.revision() == revision + 1);
  CHECK_THROWS_AS(p.reg.addCheck({"nope"}, [](const ParamRegistry&) { return std::string(); }), ParamError);
}

TEST_CASE("params: setAll and assignAll check once at the end, so order does not matter, errors undo all") {
  Pair p;
  // Moving both above the old hi: one at a time, "lo = 5" would fail first.
  p.reg.assignAll({"lo=5", "hi=6"});
  CHECK(p.lo == 5.0f);
  CHECK(p.hi == 6.0f);
  CHECK(p.error([&] { p.reg.assignAll({"hi=1", "lo=0.5", "lo=3"}); }) == "lo = 3 is not below hi = 1");
  CHECK(p.lo == 5.0f);
  CHECK(p.hi == 6.0f);
  std::size_t failed = 99;
  CHECK(p.error([&] { p.reg.setAll({{"lo", "1"}, {"hi", "11"}}, &failed); }).find("bad value '11' for hi") == 0);
  CHECK(failed == 1);
  CHECK(p.lo == 5.0f);
  p.reg.resetDefaults();
  CHECK(p.lo == 1.0f);
  CHECK(p.hi == 2.0f);
  const auto saved = p.reg.snapshot();
  p.reg.assignAll({"hi=9", "lo=8"});
  p.reg.restore(saved);
  CHECK(p.lo == 1.0f);
}

TEST_CASE("presets: a check that fails names the preset's line that set the value, at validate and apply") {
  Pair p;
  const std::string path = tempPath("checked.txt");
  { std::ofstream(path) << "[ok]\nlo = 3\nhi = 4\n\n[bad]\n# lo alone is fine\nhi = 0.5\n\nlo = 0.7\n[none]\n"; }
  const PresetFile file = PresetFile::load(path);
  const std::string expected = path + ":9: in preset 'bad': lo = 0.7 is not below hi = 0.5";
  CHECK(p.error([&] { file.validate(p.reg); }) == expected);
  CHECK(p.error([&] { file.apply("bad", p.reg); }) == expected);
  CHECK(p.lo == 1.0f);
  file.apply("ok", p.reg);
  CHECK(p.hi == 4.0f);
}

TEST_CASE("params: the panel lists the ungrouped parameters first, then each group together") {
  ParamRegistry r;
  float a = 0, gx = 0, b = 0, hy = 0, gz = 0, cam = 0;
  r.add("a", &a, 0, 1, "");
  r.add("g.x", &gx, 0, 1, "");
  r.add("b", &b, 0, 1, "");  // declared after group g: shown before it, not under its header
  r.add("h.y", &hy, 0, 1, "");
  r.add("g.z", &gz, 0, 1, "");  // g again: with g.x, not as a second g header after h
  r.add("camera.yaw", &cam, 0, 1, "").hidden = true;
  std::vector<std::string> names;
  for (const Param* p : r.panelOrder()) names.push_back(p->name);
  CHECK(names == std::vector<std::string>{"a", "b", "g.x", "g.z", "h.y"});
  CHECK(r.params().size() == 6);  // the registry's own order (presets, --list-params) is unchanged
  CHECK(r.params()[2].name == "b");
}

TEST_CASE("params: a number choice stores the number itself, refuses any other, and cycles by hotkey") {
  ParamRegistry reg;
  int texels = 2048;
  reg.addNumberChoice("map_size", &texels, {256, 1024, 2048, 4096}, "texels per side");
  CHECK(reg.get("map_size") == "2048");
  CHECK(reg.find("map_size")->defaultValue == "2048");
  CHECK(choiceIndex(*reg.find("map_size")) == 2);
  reg.set("map_size", "256");
  CHECK(texels == 256);
  CHECK(choiceIndex(*reg.find("map_size")) == 0);
  try {
    reg.set("map_size", "512");
    FAIL("512 is not a choice");
  } catch (const ParamError& e) {
    CHECK(std::string(e.what()) == "bad value '512' for map_size (choice); valid: 256, 1024, 2048, 4096");
  }
  CHECK(texels == 256);
  CHECK_THROWS_AS(reg.set("map_size", "0"), ParamError);  // never an index
  reg.find("map_size");
  texels = 4096;
  CHECK(reg.get("map_size") == "4096");
  texels = 300;  // set behind the registry's back: named as the number, and no choice's index
  CHECK(reg.get("map_size") == "300");
  CHECK(choiceIndex(*reg.find("map_size")) == -1);
  reg.resetDefaults();
  CHECK(texels == 2048);
  CHECK_THROWS_AS(reg.addNumberChoice("none", &texels, {}, "no values"), ParamError);
}

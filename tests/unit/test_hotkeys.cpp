// Hotkeys: the problems a lesson's bindings can have, each caught with its key and parameters
// named, and what a key does to each kind of parameter; the panel's slider style.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "core/hotkeys.hpp"
#include "core/slider_style.hpp"

using namespace shadowlab;

namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

struct Values {
  bool a = false, b = true;
  int choice = 0;
  float offset = 0.5f, zero = 0.0f, positive = 2.0f;
  int count = 3;
  glm::vec3 position{1.0f};
};

}  // namespace

TEST_CASE("hotkeys: a clean registry has no problems and lists every key") {
  Values v;
  ParamRegistry r;
  r.add("a", &v.a, "a bool").hotkey = "B";
  r.addChoice("choice", &v.choice, {"x", "y", "z"}, "a choice").hotkey = "V";
  r.add("offset", &v.offset, 0, 4, "a float").hotkey = "N";
  r.add("count", &v.count, 0, 8, "an int").hotkey = "1";
  CHECK(hotkeyProblems(r).empty());
  const std::string table = describeHotkeys(r);
  CHECK(table.find("N  offset  0 <-> 0.5") != std::string::npos);
  CHECK(table.find("V  choice  next choice") != std::string::npos);
  CHECK(table.find("R  (framework)") != std::string::npos);
}

TEST_CASE("hotkeys: a key bound twice, a framework key, a vector and a number that cannot toggle are refused") {
  Values v;
  ParamRegistry r;
  r.add("a", &v.a, "first").hotkey = "T";
  r.add("b", &v.b, "second on the same key").hotkey = "T";
  r.add("reload_clash", &v.count, 0, 8, "on the framework's reload key").hotkey = "R";
  r.add("fly_clash", &v.choice, 0, 8, "on a fly-camera key").hotkey = "W";
  r.add("position", &v.position, -1, 1, "a vector").hotkey = "P";
  r.add("zero", &v.zero, 0, 1, "default 0").hotkey = "Z";
  r.add("positive", &v.positive, 1, 4, "0 out of range").hotkey = "K";
  r.add("bad_key", &v.offset, 0, 4, "not a key").hotkey = "F1";
  const auto problems = hotkeyProblems(r);
  CHECK(problems.size() == 7);
  CHECK(mentions(problems, "hotkey 'T' of b: already bound to a"));
  CHECK(mentions(problems, "hotkey 'R' of reload_clash: already bound to the framework (reload shaders"));
  CHECK(mentions(problems, "hotkey 'W' of fly_clash: already bound to the framework (fly camera: forward)"));
  CHECK(mentions(problems, "hotkey 'P' of position: a key can drive a bool, a choice or a number"));
  CHECK(mentions(problems, "hotkey 'Z' of zero: its default is 0"));
  CHECK(mentions(problems, "hotkey 'K' of positive: its range"));
  CHECK(mentions(problems, "hotkey 'F1' of bad_key: not a key; valid: 0-9, A-Z"));
}

TEST_CASE("hotkeys: a bool toggles, a choice steps and wraps, a number toggles between 0 and its default") {
  Values v;
  ParamRegistry r;
  r.add("a", &v.a, "a bool").hotkey = "B";
  r.addChoice("choice", &v.choice, {"x", "y", "z"}, "a choice").hotkey = "V";
  r.add("offset", &v.offset, 0, 4, "a float").hotkey = "N";
  r.add("count", &v.count, 0, 8, "an int").hotkey = "1";
  CHECK(applyHotkey(r, "B"));
  CHECK(v.a);
  for (int expected : {1, 2, 0}) {
    CHECK(applyHotkey(r, "V"));
    CHECK(v.choice == expected);
  }
  r.set("offset", "1.5");  // moved off its default: the key sets 0, then brings the default back
  CHECK(applyHotkey(r, "N"));
  CHECK(v.offset == 0.0f);
  CHECK(applyHotkey(r, "N"));
  CHECK(v.offset == 0.5f);
  CHECK(applyHotkey(r, "1"));
  CHECK(v.count == 0);
  CHECK(applyHotkey(r, "1"));
  CHECK(v.count == 3);
  CHECK_FALSE(applyHotkey(r, "Y"));
  int texels = 1024;  // a number choice steps through its numbers, not through indices
  r.addNumberChoice("size", &texels, {256, 1024, 4096}, "a size").hotkey = "S";
  for (int expected : {4096, 256, 1024}) {
    CHECK(applyHotkey(r, "S"));
    CHECK(texels == expected);
  }
}

TEST_CASE("slider style: small values keep their digits, decades and tiny ranges slide logarithmically") {
  char text[32];
  std::snprintf(text, sizeof text, sliderStyle(0.0f, 0.05f).format, 0.0005f);
  CHECK(std::string(text) == "0.0005");  // was "0.001" with three decimals
  std::snprintf(text, sizeof text, sliderStyle(0.0f, 1.0f).format, 2e-5f);
  CHECK(std::string(text) == "2e-05");                // was "0.000"
  CHECK(sliderStyle(0.0f, 0.05f).logarithmic);        // a bias: all of it is small
  CHECK(sliderStyle(0.01f, 100.0f).logarithmic);      // a near plane: four decades
  CHECK_FALSE(sliderStyle(0.0f, 1.0f).logarithmic);   // ambient: linear
  CHECK_FALSE(sliderStyle(1.0f, 64.0f).logarithmic);  // under two decades: linear
  CHECK_FALSE(sliderStyle(-1.0f, 1.0f).logarithmic);  // a direction component
}

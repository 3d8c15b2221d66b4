#include <doctest/doctest.h>

#include <cstdio>
#include <utility>

#include "core/cli.hpp"

using namespace shadowlab;

static CommandLine parse(std::vector<std::string> args) {
  args.insert(args.begin(), "lesson");
  return parseCommandLine(args);
}
static std::string errorOf(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const CliError& e) { return e.what(); }
  return "no error";
}

TEST_CASE("cli: the shared flags parse, with both value styles") {
  const auto cl = parse({"--headless", "--size", "640x360", "--frames=5", "--screenshot", "a.png", "--set",
                         "ambient=0.2", "--set=mode=depth", "--preset", "acne", "--bench", "b.csv", "--ui-scale", "2"});
  CHECK(cl.headless);
  CHECK(cl.width == 640);
  CHECK(cl.height == 360);
  CHECK(cl.frames == 5);
  CHECK(cl.screenshot == "a.png");
  CHECK(cl.sets == std::vector<std::string>{"ambient=0.2", "mode=depth"});
  CHECK(cl.preset == "acne");
  CHECK(cl.bench == "b.csv");
  CHECK(cl.uiScale == 2.0f);
}

TEST_CASE("cli: headless defaults to a few frames, windowed runs until closed") {
  CHECK(parse({"--headless"}).frames == 3);
  CHECK(parse({}).frames == -1);
  CHECK(parse({}).width == 1280);
}

TEST_CASE("cli: --exercises runs offscreen (it only prints, and the launcher calls it without a display)") {
  const auto cl = parse({"--exercises"});
  CHECK(cl.exercises);
  CHECK(cl.headless);
}

TEST_CASE("cli: bad input is one line naming it and the valid choices") {
  const std::string unknown = errorOf({"--headles"});
  CHECK(unknown.rfind("unknown flag '--headles'; valid: --headless, --size", 0) == 0);
  CHECK(unknown.find('\n') == std::string::npos);
  CHECK(errorOf({"--size", "640"}) == "--size: '640' is not WxH, e.g. 1280x720");
  CHECK(errorOf({"--size", "0x10"}) == "--size: '0' is not a whole number in [16, 8192]");
  CHECK(errorOf({"--size", "16384x16384"}) == "--size: '16384' is not a whole number in [16, 8192]");
  CHECK(errorOf({"--frames", "-2"}) == "--frames: '-2' is not a whole number in [1, 100000000]");
  CHECK(errorOf({"--frames"}) == "--frames needs a value: --frames N");
  CHECK(errorOf({"--set", "ambient"}) == "--set: 'ambient' is not NAME=VALUE");
  CHECK(errorOf({"--ui-scale", "9"}) == "--ui-scale: '9' is not a number in [0.5, 4]");
  CHECK(errorOf({"--headless=1"}) == "--headless takes no value");
  CHECK(errorOf({"--record", "a", "--replay", "b"}) == "--record and --replay exclude each other");
}

TEST_CASE("cli: --panel names the panel's parameters (a lesson inside a slide) and opens it") {
  const auto cl = parse({"--panel", "bias.constant,bias.slope"});
  CHECK(cl.panelOnly == std::vector<std::string>{"bias.constant", "bias.slope"});
  CHECK(cl.showPanel);
  CHECK(cl.showUi);
  CHECK(parse({"--panel=fit"}).panelOnly == std::vector<std::string>{"fit"});
  CHECK(errorOf({"--panel", "a,,b"}) == "--panel: 'a,,b' has an empty name (NAME,NAME,...)");
  CHECK(errorOf({"--panel", "a,"}) == "--panel: 'a,' has an empty name (NAME,NAME,...)");
  CHECK(errorOf({"--panel", ",a"}) == "--panel: ',a' has an empty name (NAME,NAME,...)");
}

TEST_CASE("cli: an empty value is an error, never a silently dropped output") {
  CHECK(errorOf({"--screenshot="}) == "--screenshot needs a value, got an empty one: --screenshot FILE");
  CHECK(errorOf({"--measure="}) == "--measure needs a value, got an empty one: --measure FILE");
  CHECK(errorOf({"--replay="}) == "--replay needs a value, got an empty one: --replay FILE[@T|@T0..T1]");
  CHECK(errorOf({"--preset="}) == "--preset needs a value, got an empty one: --preset NAME");
  CHECK(errorOf({"--bench", ""}) == "--bench needs a value, got an empty one: --bench FILE");
  CHECK(errorOf({"--record="}) == "--record needs a value, got an empty one: --record FILE");
  CHECK(errorOf({"--set="}) == "--set needs a value, got an empty one: --set NAME=VALUE");
  CHECK(errorOf({"--size="}) == "--size needs a value, got an empty one: --size WxH");
}

TEST_CASE("cli: help lists every flag") {
  const std::string help = commandLineHelp("lesson_01");
  for (const char* flag : {"--headless", "--size", "--frames", "--screenshot", "--set", "--preset", "--bench",
                           "--list-params", "--list-presets", "--keys", "--drop", "--help"})
    CHECK(help.find(flag) != std::string::npos);
}

TEST_CASE("cli: --keys scripts key steps, --drop a file and its frame; bad ones name the value") {
  const CommandLine cl = parse({"--headless", "--frames", "20", "--keys", "Tab,W*10,Home,7,F1", "--drop", "a@b.obj@4"});
  REQUIRE(cl.keys.size() == 5);
  CHECK(cl.keys[0].name == "Tab");
  CHECK(cl.keys[0].frames == 1);
  CHECK(cl.keys[1].name == "W");
  CHECK(cl.keys[1].frames == 10);
  CHECK(cl.keys[3].name == "7");
  CHECK(cl.keys[4].name == "F1");
  CHECK(cl.drop == "a@b.obj");
  CHECK(cl.dropFrame == 4);
  const CommandLine plain = parse({"--drop", "me@home.obj"});  // no @N: the whole name, frame 1
  CHECK(plain.drop == "me@home.obj");
  CHECK(plain.dropFrame == 1);
  CHECK(errorOf({"--keys", "Tab,,W"}).rfind("--keys: '' is not a key (valid: A-Z, 0-9, Tab, Home, F1", 0) == 0);
  CHECK(errorOf({"--keys", "Shift"}).rfind("--keys: 'Shift' is not a key", 0) == 0);
  CHECK(errorOf({"--keys", "W*0"}) == "--keys W: '0' is not a whole number in [1, 100000]");
  CHECK(errorOf({"--keys", "W*x"}) == "--keys W: 'x' is not a whole number in [1, 100000]");
  CHECK(errorOf({"--headless", "--keys", "W*3"}) == "no error");  // three frames, three steps held
  CHECK(errorOf({"--headless", "--keys", "W*4"}) == "--keys: the steps take 4 frames, the run has 3 (--frames N)");
  CHECK(errorOf({"--headless", "--drop", "m.obj@3"}) == "--drop m.obj@3: the run has frames 0 to 2 (--frames N)");
  CHECK(errorOf({"--drop", "@2"}) == "--drop: '@2' names no file: --drop FILE[@N]");
}

TEST_CASE("cli: a view's command line reads back through a POSIX shell to the same sets") {
  const std::vector<std::pair<std::string, std::string>> sets = {
      {"camera.yaw", "0.6"}, {"light0.direction", "-0.5 0.2 -0.8"}, {"label", "it's \"quoted\" $HOME `x`"}};
  const std::string line = viewCommandLine("build/default/bin/lesson_03_shadow_quality", sets);
  CHECK(line.rfind("build/default/bin/lesson_03_shadow_quality --set camera.yaw=0.6 --set '", 0) == 0);
  // The shell splits it into words (printf puts one per line); the words parse to the same sets.
  FILE* shell = popen(("printf '%s\\n' " + line).c_str(), "r");
  REQUIRE(shell != nullptr);
  std::vector<std::string> words;
  std::string word;
  for (int c; (c = std::fgetc(shell)) != EOF;) {
    if (c != '\n') word += char(c);
    else words.push_back(std::exchange(word, ""));
  }
  CHECK(pclose(shell) == 0);
  std::vector<std::string> expected;
  for (const auto& [name, value] : sets) expected.push_back(name + "=" + value);
  CHECK(parseCommandLine(words).sets == expected);  // words[0] is the program, skipped as argv[0]
}

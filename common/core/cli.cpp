#include "core/cli.hpp"
#include "core/hotkeys.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace shadowlab {
namespace {

struct Flag {
  const char* name;
  const char* arg;  // nullptr: a switch
  const char* help;
};

constexpr Flag kFlags[] = {
    {"--headless", nullptr, "render offscreen, no window (tests, benchmarks, slides)"},
    {"--size", "WxH", "framebuffer size, default 1280x720; 16 to 8192 a side, and within the GL limits"},
    {"--frames", "N", "render N frames then exit (headless default 3)"},
    {"--screenshot", "FILE", "write the last frame as PNG"},
    {"--set", "NAME=VALUE", "set a parameter (repeatable; after --preset)"},
    {"--preset", "NAME", "start from a named preset (see --list-presets)"},
    {"--model", "FILE", "draw a model file (OBJ + MTL, glTF 2.0 .gltf/.glb) on the ground: sets scene=model"},
    {"--bench", "FILE", "write per-pass GPU and CPU ms of every frame as CSV"},
    {"--measure", "FILE",
     "measure the last frame against ground truth: figures as JSON, heatmaps as PNG (FILE with %d: every frame)"},
    {"--record", "FILE", "record the camera and light path while you move (windowed)"},
    {"--replay", "FILE[@T|@T0..T1]",
     "replay a recorded camera and light path over the frames (@T: hold at time T; @T0..T1: play from T0 to T1)"},
    {"--ui-scale", "S", "UI scale for projectors, 0.5 to 4 (Ctrl +/- at run time)"},
    {"--show-ui", nullptr, "headless: draw the UI into the screenshot"},
    {"--ui-layout", "FILE", "write the last frame's UI rectangles (header, panel, help, A/B labels) as JSON"},
    {"--show-help", nullptr, "draw the F1 help (and the UI) from the first frame, e.g. into a screenshot"},
    {"--show-stats", nullptr, "draw the F2 stats (renderer, passes, every counter) and the UI from the first frame"},
    {"--show-panel", nullptr, "draw the parameter panel open (F3) and the UI from the first frame"},
    {"--panel", "NAME,NAME",
     "the parameter panel open with only these parameters and no other window: a lesson inside a slide"},
    {"--keys", "LIST",
     "press keys through the window's key handler, one after the other from the first frame: \"Tab,W*10,Home\" "
     "(KEY*N: held N frames; A-Z, 0-9, Tab, Home, F1, F2, F3, F4); tests and slides script the fly camera and hotkeys"},
    {"--drop", "FILE[@N]", "drop FILE on the window before frame N (default 1), as dragging it there does"},
    {"--fullscreen", nullptr, "start fullscreen (F11 toggles)"},
    {"--strict-gl", nullptr, "fail (exit 3) on any OpenGL error (tests set it)"},
    {"--list-params", nullptr, "list every parameter with its range, default and purpose"},
    {"--list-presets", nullptr, "list the presets, one per line"},
    {"--list-hotkeys", nullptr, "list every key: the framework's and the lesson's, with what each does"},
    {"--info", nullptr,
     "print the lesson's number, title, summary, difficulty, time in class, prerequisites and exercises as JSON"},
    {"--exercises", nullptr, "run the lesson's public exercise cases and print each exercise's state (offscreen)"},
    {"--help", nullptr, "this text"},
};

std::string flagList() {
  std::string s;
  for (const auto& f : kFlags) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

int toInt(const std::string& flag, const std::string& v, int lo, int hi) {
  int out = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  if (ec != std::errc() || p != v.data() + v.size() || out < lo || out > hi)
    throw CliError(flag + ": '" + v + "' is not a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                   "]");
  return out;
}

bool keyNameValid(const std::string& k) {
  if (k.size() == 1) return (k[0] >= 'A' && k[0] <= 'Z') || (k[0] >= '0' && k[0] <= '9');
  return k == "Tab" || k == "Home" || k == "F1" || k == "F2" || k == "F3" || k == "F4";
}

}  // namespace

std::vector<ScriptedKey> parseKeyScript(const std::string& list) {
  std::vector<ScriptedKey> keys;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string step = list.substr(start, comma - start);
    const std::size_t star = step.find('*');
    ScriptedKey k{step.substr(0, star)};
    if (!keyNameValid(k.name))
      throw CliError("--keys: '" + step +
                     "' is not a key (valid: A-Z, 0-9, Tab, Home, F1, F2, F3, F4, each as KEY or KEY*N to " +
                     "hold it N frames, separated by commas, e.g. \"Tab,W*10,Home\")");
    if (star != std::string::npos) k.frames = toInt("--keys " + k.name, step.substr(star + 1), 1, kMaxKeyFrames);
    keys.push_back(k);
    start = comma + 1;
  }
  return keys;
}

namespace {

// --drop FILE@N: N digits; a file name with an '@' of its own stays whole.
void parseDrop(const std::string& value, CommandLine& cl) {
  auto at = value.rfind('@');
  if (at != std::string::npos &&
      (at + 1 == value.size() || value.find_first_not_of("0123456789", at + 1) != std::string::npos))
    at = std::string::npos;
  cl.drop = value.substr(0, at);
  if (at != std::string::npos) cl.dropFrame = toInt("--drop " + cl.drop, value.substr(at + 1), 0, 100000000);
  if (cl.drop.empty()) throw CliError("--drop: '" + value + "' names no file: --drop FILE[@N]");
}

// What the flags say together: a step or a drop past the last frame would never happen, so say so
// rather than run without it.
void checkTogether(const CommandLine& cl) {
  if (!cl.record.empty() && !cl.replay.empty()) throw CliError("--record and --replay exclude each other");
  long keyFrames = 0;
  for (const ScriptedKey& k : cl.keys) keyFrames += k.frames;
  if (cl.frames > 0 && keyFrames > cl.frames)
    throw CliError("--keys: the steps take " + std::to_string(keyFrames) + " frames, the run has " +
                   std::to_string(cl.frames) + " (--frames N)");
  if (!cl.drop.empty() && cl.frames > 0 && cl.dropFrame >= cl.frames)
    throw CliError("--drop " + cl.drop + "@" + std::to_string(cl.dropFrame) + ": the run has frames 0 to " +
                   std::to_string(cl.frames - 1) + " (--frames N)");
}

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  CommandLine cl;
  bool framesGiven = false;
  if (const char* s = std::getenv("SHADOWLAB_STRICT_GL")) cl.strictGl = std::string(s) == "1";
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string flag = args[i], value;
    bool hasInlineValue = false;
    if (const auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
      hasInlineValue = true;
    }
    const Flag* def = nullptr;
    for (const auto& f : kFlags)
      if (flag == f.name) def = &f;
    if (!def) throw CliError("unknown flag '" + args[i] + "'; valid: " + flagList());
    if (def->arg && !hasInlineValue) {
      if (i + 1 >= args.size()) throw CliError(flag + " needs a value: " + flag + " " + def->arg);
      value = args[++i];
    } else if (!def->arg && hasInlineValue) {
      throw CliError(flag + " takes no value");
    }
    if (def->arg && value.empty())  // "--screenshot=" would otherwise switch the output off silently
      throw CliError(flag + " needs a value, got an empty one: " + flag + " " + def->arg);
    if (flag == "--headless") cl.headless = true;
    else if (flag == "--size") {
      const auto x = value.find('x');
      if (x == std::string::npos) throw CliError("--size: '" + value + "' is not WxH, e.g. 1280x720");
      cl.width = toInt("--size", value.substr(0, x), 16, kMaxFramebufferSide);
      cl.height = toInt("--size", value.substr(x + 1), 16, kMaxFramebufferSide);
    } else if (flag == "--frames") {
      cl.frames = toInt("--frames", value, 1, 100000000);
      framesGiven = true;
    } else if (flag == "--screenshot") cl.screenshot = value;
    else if (flag == "--set") {
      if (value.find('=') == std::string::npos || value.front() == '=')
        throw CliError("--set: '" + value + "' is not NAME=VALUE");
      cl.sets.push_back(value);
    } else if (flag == "--preset") cl.preset = value;
    else if (flag == "--model") cl.model = value;
    else if (flag == "--bench") cl.bench = value;
    else if (flag == "--measure") cl.measure = value;
    else if (flag == "--record") cl.record = value;
    else if (flag == "--replay") cl.replay = value;
    else if (flag == "--ui-scale") {
      char* end = nullptr;
      const float s = std::strtof(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !(s >= 0.5f && s <= 4.0f))
        throw CliError("--ui-scale: '" + value + "' is not a number in [0.5, 4]");
      cl.uiScale = s;
    } else if (flag == "--show-ui") cl.showUi = true;
    else if (flag == "--show-help") cl.showUi = cl.showHelp = true;
    else if (flag == "--show-stats") cl.showUi = cl.showStats = true;
    else if (flag == "--show-panel") cl.showUi = cl.showPanel = true;
    else if (flag == "--panel") {
      cl.showUi = cl.showPanel = true;
      for (std::size_t at = 0; at <= value.size();) {
        const std::size_t comma = std::min(value.find(',', at), value.size());
        if (comma == at) throw CliError("--panel: '" + value + "' has an empty name (NAME,NAME,...)");
        cl.panelOnly.push_back(value.substr(at, comma - at));
        at = comma + 1;
      }
    } else if (flag == "--ui-layout") cl.uiLayout = value;
    else if (flag == "--keys") cl.keys = parseKeyScript(value);
    else if (flag == "--drop") parseDrop(value, cl);
    else if (flag == "--fullscreen") cl.fullscreen = true;
    else if (flag == "--strict-gl") cl.strictGl = true;
    else if (flag == "--list-params") cl.listParams = true;
    else if (flag == "--list-presets") cl.listPresets = true;
    else if (flag == "--list-hotkeys") cl.listHotkeys = true;
    else if (flag == "--info") cl.info = true;
    else if (flag == "--exercises") cl.exercises = cl.headless = true;  // it only prints: no window (the launcher)
    else if (flag == "--help") cl.help = true;
  }
  if (cl.headless && !framesGiven) cl.frames = 3;
  checkTogether(cl);
  return cl;
}

CommandLine parseCommandLine(int argc, char** argv) {
  return parseCommandLine(std::vector<std::string>(argv, argv + argc));
}

std::string commandLineHelp(const std::string& program) {
  std::string s = "usage: " + program + " [flags]\n";
  for (const auto& f : kFlags) {
    std::string left = std::string("  ") + f.name + (f.arg ? std::string(" ") + f.arg : "");
    if (left.size() < 26) left.resize(26, ' ');
    s += left + " " + f.help + "\n";
  }
  s += "Keys (windowed): " + functionKeys(", ") +
       ",\nR reload shaders, H hide the UI, WASD Q/E and the mouse fly the camera; --list-hotkeys lists the lesson's "
       "own keys.\n";
  return s;
}

namespace {
// A word as a POSIX shell reads it back: bare when it holds only safe characters, else in single
// quotes (a quote inside as '\'').
std::string shellWord(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=.,/:") == std::string::npos;
  if (safe) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

std::string viewCommandLine(const std::string& program, const std::vector<std::pair<std::string, std::string>>& sets) {
  std::string out = shellWord(program);
  for (const auto& [name, value] : sets) out += " --set " + shellWord(name + "=" + value);
  return out;
}

}  // namespace shadowlab

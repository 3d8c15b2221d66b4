#pragma once
// The command line every lesson shares. Parsing is GL-free so it is unit-tested; the app layer
// (common/app) acts on the result. Any bad flag, parameter, value or preset is a CliError whose
// message is one line naming it and the valid choices; lessons exit with code 2 on it.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

struct CliError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// --size's bound a side. 16384x16384 took 81 s and 2.3 GB a frame on llvmpipe, whose GL limits
// allow it; the context also checks the GL limits of the machine (gl::framebufferSizeProblem).
inline constexpr int kMaxFramebufferSide = 8192;

// One step of --keys: a key pressed through the window's key handler, then held for `frames` frames
// (the fly camera moves while W, A, S, D, Q or E is held). Names: A-Z, 0-9, Tab, Home, F1.
struct ScriptedKey {
  std::string name;
  int frames = 1;
};
inline constexpr int kMaxKeyFrames = 100000;

struct CommandLine {
  bool headless = false;
  int width = 1280, height = 720;
  int frames = -1;                // -1: run until closed (windowed); headless default 3
  std::string screenshot;         // write the last frame here (PNG)
  std::vector<std::string> sets;  // "name=value", applied after the preset, in order
  std::string preset;
  std::string model;       // a model file for scene=model (core/model_file)
  std::string bench;       // per-pass GPU and CPU ms over the frames, CSV
  std::string measure;     // ground-truth error figures of the last frame, JSON
  std::string record;      // record the camera/light path to this file (windowed)
  std::string replay;      // replay a recorded path over the frames
  float uiScale = 0;       // 0: automatic (from the monitor's content scale)
  bool showUi = false;     // headless: draw the UI into the screenshot too
  bool showHelp = false;   // the F1 help open from the first frame (implies showUi)
  bool showStats = false;  // the F2 stats open from the first frame (implies showUi)
  bool showPanel = false;  // the parameter panel open (F3) from the first frame (implies showUi)
  // --panel a,b: the panel open with these parameters only, and no other window (a lesson inside a
  // slide: the picture and the few knobs the slide is about). Implies showPanel.
  std::vector<std::string> panelOnly;
  std::string uiLayout;  // the last frame's UI rectangles, JSON (tests: nothing overlaps)
  bool fullscreen = false;
  std::vector<ScriptedKey> keys;  // --keys "Tab,W*10,Home": pressed one after the other, from frame 0
  std::string drop;               // --drop FILE[@N]: dropped on the window before frame N (default 1)
  int dropFrame = 1;
  bool listParams = false, listPresets = false, listHotkeys = false, help = false, info = false;
  bool exercises = false;  // print each exercise's state from the public cases (needs a GL context), exit
  bool strictGl = false;   // any GL error fails the run (tests); also SHADOWLAB_STRICT_GL=1
};

// "Tab,W*10,Home" into its steps. Throws CliError naming the bad step and the valid names.
std::vector<ScriptedKey> parseKeyScript(const std::string& list);

// argv[0] is skipped. Throws CliError.
CommandLine parseCommandLine(const std::vector<std::string>& args);
CommandLine parseCommandLine(int argc, char** argv);
// The --help text (flags, with what each does).
std::string commandLineHelp(const std::string& program);
// The command line that opens a view: PROGRAM --set 'name=value' ... for each (name, value), every
// word that needs it single-quoted for a POSIX shell: what "copy link" gives natively (the browser
// gives the URL). parseCommandLine of its words gives the same sets back.
std::string viewCommandLine(const std::string& program, const std::vector<std::pair<std::string, std::string>>& sets);

}  // namespace shadowlab

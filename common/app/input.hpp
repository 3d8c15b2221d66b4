#pragma once
// Mouse and keys onto the camera and the framework's toggles. Input handling lives here, apart
// from the camera maths (core/camera), which stays pure and unit-tested.
#include <functional>
#include <string>
#include <vector>

#include "core/cli.hpp"

#include "core/hotkeys.hpp"
#include "core/params.hpp"

struct GLFWwindow;

namespace shadowlab {

struct OrbitCamera;

struct Input {
  double lastX = 0, lastY = 0;
  bool haveLast = false;
  float scroll = 0;
  bool help = false;
  bool stats = false;             // F2: the renderer, the pass table and every counter, under the header
  bool panel = false;             // F3: the parameter panel open (else a title bar: the picture first)
  bool referencePicture = false;  // F4: the reference's picture of the preset in view (app/reference_picture.hpp)
  bool screenshot = false;
  int uiHidden = 0;          // H: 1 the panels hidden (the labels and legends that explain the picture stay), 2 none
  bool fly = false;          // Tab: WASD + mouse look instead of orbiting the target
  float flySpeed = 1.0f;     // half the camera distance a second, times this; the wheel scales it
  bool resetCamera = false;  // Home: back to the pose the run started with
  int uiScaleSteps = 0;
  bool toggleFullscreen = false;
  std::vector<int> pressed;  // plain key presses, for parameter hotkeys
  bool draggingDivider = false;
  std::vector<std::string> dropped;  // files dropped on the window (a model to load)
  bool quit = false;                 // Esc
};

// What the window's key and drop callbacks do, and all they do: --keys and --drop call the same
// functions headless, so a test drives exactly the code a lecturer's keyboard and mouse drive.
void pressKey(Input& input, int key, int mods);
void dropFiles(Input& input, const std::vector<std::string>& paths);

// --keys: each step's key pressed through pressKey at the start of a frame, then held for its
// frames (held() answers for the fly keys, beside the window's own key state); the next step starts
// the frame after. done() names the step that ended with this frame, "" otherwise.
class KeyScript {
 public:
  KeyScript() = default;
  explicit KeyScript(std::vector<ScriptedKey> steps) : steps_(std::move(steps)) {}
  void beginFrame(Input& input);  // call before the frame's input is handled
  bool held(int key) const;
  std::string endFrame();  // call after the frame's input is handled
  bool empty() const { return steps_.empty(); }

 private:
  std::vector<ScriptedKey> steps_;
  std::size_t next_ = 0;
  int key_ = -1, left_ = 0;  // the step in progress: its GLFW key, the frames it is still held
};
// The GLFW key of a --keys name ("W", "7", "Tab", "Home", "F1").
int scriptedKeyCode(const std::string& name);

// Routes the window's scroll and key events into `input` (one window per process). Call again
// after ImGui installs its own callbacks, so ours are chained in front.
void installInputCallbacks(GLFWwindow* window, Input* input);
void uninstallInputCallbacks();

// What the mouse does this frame: orbit (left drag), pan (right drag), zoom (wheel), or drag the
// A/B divider when `divider` is non-null and the press starts on it. `uiHasMouse`: ImGui owns it.
// In fly mode the left drag looks around the eye and the wheel sets the speed.
void applyMouse(GLFWwindow* window, Input& input, bool uiHasMouse, OrbitCamera& camera, float* divider);
// Fly mode: W/S forward and back, A/D sideways, Q/E down and up while held, for `seconds`.
// `held(key)`: the window's key state, or a --keys script's.
void applyFlyKeys(const std::function<bool(int)>& held, const Input& input, OrbitCamera& camera, float seconds);

// "A".."Z", "0".."9" for a GLFW key, "" otherwise.
std::string keyName(int key);
bool isReloadKey(int key);

}  // namespace shadowlab

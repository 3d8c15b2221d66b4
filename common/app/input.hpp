#pragma once
// Mouse and keys onto the camera and the framework's toggles. Input handling lives here, apart
// from the camera maths (core/camera), which stays pure and unit-tested.
#include <string>
#include <vector>

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
  bool screenshot = false;
  bool uiHidden = false;     // H: no UI at all, the picture alone (the projector)
  bool fly = false;          // Tab: WASD + mouse look instead of orbiting the target
  float flySpeed = 1.0f;     // half the camera distance a second, times this; the wheel scales it
  bool resetCamera = false;  // Home: back to the pose the run started with
  int uiScaleSteps = 0;
  bool toggleFullscreen = false;
  std::vector<int> pressed;  // plain key presses, for parameter hotkeys
  bool draggingDivider = false;
  std::vector<std::string> dropped;  // files dropped on the window (a model to load)
};

// Routes the window's scroll and key events into `input` (one window per process). Call again
// after ImGui installs its own callbacks, so ours are chained in front.
void installInputCallbacks(GLFWwindow* window, Input* input);
void uninstallInputCallbacks();

// What the mouse does this frame: orbit (left drag), pan (right drag), zoom (wheel), or drag the
// A/B divider when `divider` is non-null and the press starts on it. `uiHasMouse`: ImGui owns it.
// In fly mode the left drag looks around the eye and the wheel sets the speed.
void applyMouse(GLFWwindow* window, Input& input, bool uiHasMouse, OrbitCamera& camera, float* divider);
// Fly mode: W/S forward and back, A/D sideways, Q/E down and up while held, for `seconds`.
void applyFlyKeys(GLFWwindow* window, const Input& input, OrbitCamera& camera, float seconds);

// "A".."Z", "0".."9" for a GLFW key, "" otherwise.
std::string keyName(int key);
bool isReloadKey(int key);

}  // namespace shadowlab

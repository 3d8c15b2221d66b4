#pragma once
// Mouse and keys onto the camera and the framework's toggles. Input handling lives here, apart
// from the camera maths (core/camera), which stays pure and unit-tested.
#include <string>
#include <vector>

#include "core/params.hpp"

struct GLFWwindow;

namespace shadowlab {

class OrbitCamera;

struct Input {
  double lastX = 0, lastY = 0;
  bool haveLast = false;
  float scroll = 0;
  bool help = false;
  bool screenshot = false;
  int uiScaleSteps = 0;
  bool toggleFullscreen = false;
  std::vector<int> pressed;  // plain key presses, for parameter hotkeys
  bool draggingDivider = false;
};

// Routes the window's scroll and key events into `input` (one window per process). Call again
// after ImGui installs its own callbacks, so ours are chained in front.
void installInputCallbacks(GLFWwindow* window, Input* input);
void uninstallInputCallbacks();

// What the mouse does this frame: orbit (left drag), pan (right drag), zoom (wheel), or drag the
// A/B divider when `divider` is non-null and the press starts on it. `uiHasMouse`: ImGui owns it.
void applyMouse(GLFWwindow* window, Input& input, bool uiHasMouse, OrbitCamera& camera, float* divider);

// "A".."Z", "0".."9" for a GLFW key, "" otherwise.
std::string keyName(int key);
bool isReloadKey(int key);

// A hotkey toggles a bool or steps a choice to its next value. False when no parameter has it.
bool applyHotkey(ParamRegistry& params, const std::string& key);

}  // namespace shadowlab

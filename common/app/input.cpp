#include "app/input.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include "core/camera.hpp"

namespace shadowlab {
namespace {

Input* g_input = nullptr;

void onScroll(GLFWwindow*, double, double y) {
  if (g_input) g_input->scroll += float(y);
}

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
  if (!g_input || action != GLFW_PRESS) return;
  pressKey(*g_input, key, mods);
  if (g_input->quit) glfwSetWindowShouldClose(w, GLFW_TRUE);
}

void onDrop(GLFWwindow*, int count, const char** paths) {
  if (g_input) dropFiles(*g_input, std::vector<std::string>(paths, paths + count));
}

// Window width in the cursor's coordinates (screen coordinates, not framebuffer pixels).
double windowWidth(GLFWwindow* w) {
  int ww = 1, wh = 1;
  glfwGetWindowSize(w, &ww, &wh);
  return double(std::max(ww, 1));
}

}  // namespace

void pressKey(Input& input, int key, int mods) {
  const bool ctrl = mods & GLFW_MOD_CONTROL;
  if (key == GLFW_KEY_F1) input.help = !input.help;
  else if (key == GLFW_KEY_F2) input.stats = !input.stats;
  else if (key == GLFW_KEY_F3) input.panel = !input.panel;
  else if (key == GLFW_KEY_F4) input.referencePicture = !input.referencePicture;
  else if (key == GLFW_KEY_F11) input.toggleFullscreen = true;
  else if (key == GLFW_KEY_F12) input.screenshot = true;
  else if (ctrl && (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)) ++input.uiScaleSteps;
  else if (ctrl && (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)) --input.uiScaleSteps;
  else if (key == GLFW_KEY_ESCAPE) input.quit = true;
  else if (key == GLFW_KEY_TAB) input.fly = !input.fly;
  else if (key == GLFW_KEY_HOME) input.resetCamera = true;
  else if (key == GLFW_KEY_H && !ctrl) input.uiHidden = (input.uiHidden + 1) % 3;
  else if (!ctrl) input.pressed.push_back(key);
}

void dropFiles(Input& input, const std::vector<std::string>& paths) {
  input.dropped.insert(input.dropped.end(), paths.begin(), paths.end());
}

int scriptedKeyCode(const std::string& name) {
  if (name == "Tab") return GLFW_KEY_TAB;
  if (name == "Home") return GLFW_KEY_HOME;
  if (name == "F1") return GLFW_KEY_F1;
  if (name == "F2") return GLFW_KEY_F2;
  if (name == "F3") return GLFW_KEY_F3;
  if (name == "F4") return GLFW_KEY_F4;
  if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z') return GLFW_KEY_A + (name[0] - 'A');
  if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return GLFW_KEY_0 + (name[0] - '0');
  return GLFW_KEY_UNKNOWN;  // core/cli's parseKeyScript accepts no other name
}

void KeyScript::beginFrame(Input& input) {
  if (left_ > 0 || next_ >= steps_.size()) return;
  key_ = scriptedKeyCode(steps_[next_].name);
  left_ = steps_[next_].frames;
  pressKey(input, key_, 0);
}

bool KeyScript::held(int key) const { return left_ > 0 && key == key_; }

std::string KeyScript::endFrame() {
  if (left_ == 0 || --left_ > 0) return "";
  const ScriptedKey& step = steps_[next_++];
  return step.frames > 1 ? step.name + "*" + std::to_string(step.frames) : step.name;
}

void installInputCallbacks(GLFWwindow* window, Input* input) {
  g_input = input;
  if (!window) return;
  glfwSetScrollCallback(window, onScroll);
  glfwSetKeyCallback(window, onKey);
  glfwSetDropCallback(window, onDrop);
}

void uninstallInputCallbacks() { g_input = nullptr; }

void applyMouse(GLFWwindow* w, Input& input, bool uiHasMouse, OrbitCamera& camera, float* divider) {
  double x, y;
  glfwGetCursorPos(w, &x, &y);
  if (input.haveLast && !uiHasMouse) {
    const float dx = float(x - input.lastX), dy = float(y - input.lastY);
    const bool left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const double width = windowWidth(w);
    if (left && divider && (input.draggingDivider || std::abs(x - *divider * width) < 8)) {
      input.draggingDivider = true;  // the A/B divider follows the mouse
      *divider = float(x / width);
    } else if (left && input.fly) {
      camera.lookAround(-dx * 0.003f, -dy * 0.003f);  // drag right: turn right; drag up: look up
    } else if (left) {
      camera.orbit(-dx * 0.005f, dy * 0.005f);
    }
    if (!left) input.draggingDivider = false;
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) camera.pan({-dx, dy});
    if (input.scroll != 0 && input.fly)
      input.flySpeed = std::clamp(input.flySpeed * std::pow(1.25f, input.scroll), 0.01f, 100.0f);
    else if (input.scroll != 0) camera.zoom(std::pow(0.9f, input.scroll));
  }
  input.scroll = 0;
  input.lastX = x;
  input.lastY = y;
  input.haveLast = true;
}

void applyFlyKeys(const std::function<bool(int)>& held, const Input& input, OrbitCamera& camera, float seconds) {
  if (!input.fly) return;
  const auto axis = [&](int plus, int minus) { return (held(plus) ? 1.0f : 0.0f) - (held(minus) ? 1.0f : 0.0f); };
  const glm::vec3 local(axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q), axis(GLFW_KEY_W, GLFW_KEY_S));
  // Speed scales with how far the camera looks: a city block and a tabletop feel alike.
  if (local != glm::vec3(0.0f)) camera.fly(local * (input.flySpeed * 0.5f * camera.distance * seconds));
}

std::string keyName(int key) {
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + key - GLFW_KEY_A));
  return "";
}

bool isReloadKey(int key) { return key == GLFW_KEY_R; }

}  // namespace shadowlab

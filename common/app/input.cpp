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
  const bool ctrl = mods & GLFW_MOD_CONTROL;
  if (key == GLFW_KEY_F1) g_input->help = !g_input->help;
  else if (key == GLFW_KEY_F11) g_input->toggleFullscreen = true;
  else if (key == GLFW_KEY_F12) g_input->screenshot = true;
  else if (ctrl && (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)) ++g_input->uiScaleSteps;
  else if (ctrl && (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)) --g_input->uiScaleSteps;
  else if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
  else if (key == GLFW_KEY_TAB) g_input->fly = !g_input->fly;
  else if (key == GLFW_KEY_HOME) g_input->resetCamera = true;
  else if (key == GLFW_KEY_H && !ctrl) g_input->uiHidden = !g_input->uiHidden;
  else if (!ctrl) g_input->pressed.push_back(key);
}

void onDrop(GLFWwindow*, int count, const char** paths) {
  if (g_input)
    for (int i = 0; i < count; ++i) g_input->dropped.emplace_back(paths[i]);
}

// Window width in the cursor's coordinates (screen coordinates, not framebuffer pixels).
double windowWidth(GLFWwindow* w) {
  int ww = 1, wh = 1;
  glfwGetWindowSize(w, &ww, &wh);
  return double(std::max(ww, 1));
}

}  // namespace

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

void applyFlyKeys(GLFWwindow* w, const Input& input, OrbitCamera& camera, float seconds) {
  if (!input.fly) return;
  const auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  const glm::vec3 local(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                        held(GLFW_KEY_W) - held(GLFW_KEY_S));
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

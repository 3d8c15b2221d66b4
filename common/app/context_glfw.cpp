// A real window through GLFW (X11, Wayland, Cocoa, Win32), OpenGL 4.1 core forward-compatible
// (macOS's ceiling); in a build without EGL also the hidden window headless runs use.
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <stdexcept>

#include "app/offscreen_context.hpp"

namespace shadowlab {
namespace {

// GLFW initialised and a 4.1 core forward-compatible window made current (hidden for headless runs
// without EGL); throws with what to try.
GLFWwindow* openWindow(const ContextOptions& o, bool visible) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit())
    throw std::runtime_error(visible ? "GLFW: cannot initialise (no display?); run with --headless"
                                     : "GLFW: cannot initialise (no display?); this build has no EGL, so headless "
                                       "runs need a display too (a hidden window): set DISPLAY or use xvfb-run");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, o.debug ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(visible ? o.width : 64, visible ? o.height : 64, o.title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("GLFW: no OpenGL 4.1 core window; the course needs 4.1 or newer" +
                             std::string(visible ? " (try --headless)" : ""));
  }
  glfwMakeContextCurrent(window);
  gl::resetCaps();
  return window;
}

class GlfwContext final : public Context {
 public:
  explicit GlfwContext(const ContextOptions& o) : window_(openWindow(o, true)) {
    glfwSwapInterval(1);
    if (o.fullscreen) setFullscreen(true);
  }
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  unsigned framebuffer() const override { return 0; }
  int width() const override {
    int w, h;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
  }
  int height() const override {
    int w, h;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
  }
  bool headless() const override { return false; }
  bool shouldClose() const override { return glfwWindowShouldClose(window_); }
  void pollEvents() override { glfwPollEvents(); }
  void present() override { glfwSwapBuffers(window_); }
  std::string platform() const override {
#if GLFW_VERSION_MINOR >= 4
    return glfwGetPlatform() == GLFW_PLATFORM_WAYLAND ? "GLFW/Wayland" : "GLFW/X11";
#else
    return "GLFW";
#endif
  }
  GLFWwindow* window() const override { return window_; }
  bool fullscreen() const override { return glfwGetWindowMonitor(window_) != nullptr; }
  void setFullscreen(bool on) override {
    if (on == fullscreen()) return;
    if (on) {
      glfwGetWindowPos(window_, &savedX_, &savedY_);
      glfwGetWindowSize(window_, &savedW_, &savedH_);
      GLFWmonitor* monitor = glfwGetPrimaryMonitor();
      const GLFWvidmode* mode = glfwGetVideoMode(monitor);
      glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    } else {
      glfwSetWindowMonitor(window_, nullptr, savedX_, savedY_, savedW_, savedH_, 0);
    }
  }
  float contentScale() const override {
    float x = 1, y = 1;
    glfwGetWindowContentScale(window_, &x, &y);
    return x;
  }

 private:
  GLFWwindow* window_ = nullptr;
  int savedX_ = 0, savedY_ = 0, savedW_ = 1280, savedH_ = 720;
};

#ifdef SHADOWLAB_HEADLESS_GLFW
// Headless without EGL (macOS, Windows): a hidden window holds the context, frames go to an
// offscreen framebuffer of the requested size exactly as with EGL.
class HiddenWindowContext final : public OffscreenContext {
 public:
  explicit HiddenWindowContext(const ContextOptions& o) : window_(openWindow(o, false)) {
    try {
      makeFrame(o);
    } catch (...) {
      close();
      throw;
    }
  }
  ~HiddenWindowContext() override {
    releaseFrame();
    close();
  }
  std::string platform() const override { return "GLFW hidden window"; }

 private:
  void close() {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GLFWwindow* window_ = nullptr;
};
#endif

}  // namespace

#ifdef SHADOWLAB_HEADLESS_GLFW
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  return std::make_unique<HiddenWindowContext>(options);
}
#endif

bool displayAvailable() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (w && *w);
}

std::unique_ptr<Context> createWindowContext(const ContextOptions& options) {
  return std::make_unique<GlfwContext>(options);
}

}  // namespace shadowlab

#pragma once
// Where frames go. Two implementations behind one interface: a GLFW window, and headless EGL
// (Mesa's surfaceless platform, or the EGL device platform where a GPU driver offers it) rendering
// into an offscreen framebuffer; a build without EGL (macOS, Windows) renders headless frames into
// the same offscreen framebuffer from a hidden GLFW window. Lessons draw into framebuffer() and
// never assume it is 0.
#include <memory>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace shadowlab {

class Context {
 public:
  virtual ~Context() = default;
  virtual unsigned framebuffer() const = 0;  // where the frame goes (0 for a window)
  virtual int width() const = 0;             // framebuffer pixels
  virtual int height() const = 0;
  virtual bool headless() const = 0;
  virtual bool shouldClose() const = 0;
  virtual void pollEvents() = 0;
  virtual void present() = 0;                // swap buffers (window) or finish (headless)
  virtual std::string platform() const = 0;  // "GLFW/X11", "EGL surfaceless", "EGL device"...
  virtual GLFWwindow* window() const { return nullptr; }
  virtual void setFullscreen(bool) {}
  virtual bool fullscreen() const { return false; }
  virtual float contentScale() const { return 1.0f; }
  // Whether the picture is drawn after the frame's code returns (the browser: WebGL runs in its GPU
  // process once the animation frame ends), so that a frame's time is the time between frames, not
  // the time spent in the frame's code.
  virtual bool drawsAfterFrame() const { return false; }
};

struct ContextOptions {
  int width = 1280, height = 720;
  std::string title = "shadowlab";
  bool debug = true;  // ask for a debug context (KHR_debug messages)
  bool fullscreen = false;
};

// A requested size past the GL limits (--size): bad input, not a broken machine.
struct FramebufferSizeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws std::runtime_error with what failed and what to try (e.g. no DISPLAY: use --headless);
// the headless context throws FramebufferSizeError before allocating a frame past the GL limits.
std::unique_ptr<Context> createWindowContext(const ContextOptions& options);
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options);

// True when a display server is reachable (DISPLAY or WAYLAND_DISPLAY set).
bool displayAvailable();

}  // namespace shadowlab

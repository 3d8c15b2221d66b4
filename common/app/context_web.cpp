// The browser's context: the page's <canvas id="canvas"> through emscripten's GLFW, WebGL2
// (OpenGL ES 3.0). A headless run (--headless in the page's URL, what the tests use) draws into the
// same canvas with the headless rules of the native lessons (a fixed dt, no UI unless --show-ui,
// every shader waited for), so its frames match the native headless ones.
#include <GLFW/glfw3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/context.hpp"
#include "gl/caps.hpp"
#include "gl/gl.hpp"

namespace shadowlab {
namespace {

class WebContext final : public Context {
 public:
  WebContext(const ContextOptions& o, bool headless) : headless_(headless) {
    if (!glfwInit()) throw std::runtime_error("the page's GLFW (emscripten) did not initialise");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_ALPHA_BITS, 0);  // an opaque canvas: the page never shows through the picture
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    glfwWindowHint(GLFW_SAMPLES, 0);
    window_ = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
    if (!window_) throw std::runtime_error("this browser gave the page no WebGL2 context (is WebGL switched off?)");
    glfwMakeContextCurrent(window_);
    // What WebGL2 offers only when asked: the extensions gl::caps() reports and the fallbacks test.
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gl = emscripten_webgl_get_current_context();
    for (const char* e :
         {"EXT_depth_clamp", "EXT_color_buffer_float", "OES_texture_float_linear", "EXT_texture_filter_anisotropic",
          "EXT_float_blend", "WEBGL_polygon_mode", "EXT_texture_norm16"})
      emscripten_webgl_enable_extension(gl, e);
    gl::resetCaps();
  }
  ~WebContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  unsigned framebuffer() const override { return 0; }
  int width() const override { return size().first; }
  int height() const override { return size().second; }
  bool headless() const override { return headless_; }
  bool shouldClose() const override { return glfwWindowShouldClose(window_); }
  void pollEvents() override {
    glfwPollEvents();
    if (!headless_) followCanvas();
  }
  void present() override {}  // the browser shows the canvas when the animation frame returns
  std::string platform() const override { return "WebGL2 (emscripten)"; }
  GLFWwindow* window() const override { return headless_ ? nullptr : window_; }
  float contentScale() const override { return float(emscripten_get_device_pixel_ratio()); }
  bool drawsAfterFrame() const override { return true; }

 private:
  // The page sizes the canvas (the window's size, or the URL's size=WxH); the picture follows it
  // when the reader resizes the window, as a native window's does. Not in a headless run (tests).
  void followCanvas() {
    double cssWidth = 0, cssHeight = 0;
    if (emscripten_get_element_css_size("#canvas", &cssWidth, &cssHeight) != EMSCRIPTEN_RESULT_SUCCESS) return;
    const int w = std::max(320, int(std::lround(cssWidth))), h = std::max(180, int(std::lround(cssHeight)));
    // Not glfwSetWindowSize: emscripten's asks for fullscreen when the size is the screen's (a
    // maximised headless page), which the browser refuses without a click.
    if (std::pair(w, h) != size()) EM_ASM({ Browser.setCanvasSize($0, $1); }, w, h);
  }
  std::pair<int, int> size() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
  }
  GLFWwindow* window_ = nullptr;
  bool headless_ = false;
};

}  // namespace

bool displayAvailable() { return true; }  // the page is the display

std::unique_ptr<Context> createWindowContext(const ContextOptions& options) {
  return std::make_unique<WebContext>(options, false);
}
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  return std::make_unique<WebContext>(options, true);
}

}  // namespace shadowlab

#pragma once
// What the two headless contexts share (EGL, and the hidden GLFW window of a build without EGL):
// frames go to an offscreen framebuffer of the requested size, never past the GL limits.
#include "app/context.hpp"
#include "gl/caps.hpp"
#include "gl/gl.hpp"
#include "gl/objects.hpp"

namespace shadowlab {

class OffscreenContext : public Context {
 public:
  unsigned framebuffer() const override { return target_.fbo.id(); }
  int width() const override { return width_; }
  int height() const override { return height_; }
  bool headless() const override { return true; }
  bool shouldClose() const override { return false; }
  void pollEvents() override {}
  // glFinish, not glFlush: a frame is done when its pixels are, so frame times are honest.
  void present() override { glFinish(); }

 protected:
  // With the new context current: a size past its limits is FramebufferSizeError (bad input, not a
  // broken machine), else the frame is made.
  void makeFrame(const ContextOptions& o) {
    gl::resetCaps();
    if (const std::string problem = gl::framebufferSizeProblem(o.width, o.height); !problem.empty())
      throw FramebufferSizeError("--size: " + problem);
    width_ = o.width;
    height_ = o.height;
    target_ = gl::makeRenderTarget(width_, height_, "headless framebuffer");
  }
  void releaseFrame() { target_ = {}; }  // before the context goes

 private:
  int width_ = 0, height_ = 0;
  gl::RenderTarget target_;
};

}  // namespace shadowlab

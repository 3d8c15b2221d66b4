#pragma once
// The frame budget: on a software renderer (llvmpipe in a VM, over remote desktop, on a laptop
// without a usable GPU driver) an interactive window renders the 3D view at a reduced internal
// resolution chosen to hold a target frame rate, upscaled to the window, with the UI drawn on top
// at full resolution. Headless runs, screenshots and measurements always render at the requested
// size: the budget only ever touches what a person is watching.
#include <string>

#include "core/params.hpp"
#include "gl/objects.hpp"

namespace shadowlab {

class FrameBudget {
 public:
  enum class Mode { Auto, Off, Always };  // auto: on for software renderers in a window
  void declare(ParamRegistry& params);
  // Whether this frame may be scaled: a window, not a screenshot or measured frame, and the mode.
  void setAllowed(bool windowed, bool softwareRenderer, bool fullResolutionFrame);
  // The framebuffer the lesson draws into at the scale in use (the window's own when not scaled),
  // and the size to tell it. Call before the frame.
  unsigned begin(unsigned windowFbo, int width, int height, int& scaledWidth, int& scaledHeight);
  // Upscales what was drawn into the window's framebuffer (nothing when not scaled), then updates
  // the scale from this frame's time in milliseconds.
  void end(unsigned windowFbo, int width, int height);
  void record(double frameMs);
  float scale() const { return active_ ? scale_ : 1.0f; }
  // "render scale 0.60 (software renderer)" while scaling, else "".
  std::string label() const;

 private:
  Mode mode_ = Mode::Auto;
  float fps_ = 15.0f;
  float minScale_ = 0.25f;
  bool allowed_ = false, software_ = false, active_ = false;
  float scale_ = 1.0f;
  double msAvg_ = 0;
  int frames_ = 0;
  gl::RenderTarget target_;
};

// The next render scale that holds `targetMs` given a frame of `frameMs` at `scale` (the cost of a
// frame taken as roughly proportional to its pixels), moved in steps of 0.05 so it does not flicker
// between sizes, within [minScale, 1]. GL-free, for the tests.
float nextRenderScale(float scale, double frameMs, double targetMs, float minScale);

}  // namespace shadowlab

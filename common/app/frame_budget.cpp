#include "app/frame_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl/gl.hpp"

namespace shadowlab {

float nextRenderScale(float s, double ms, double targetMs, float minScale) {
  if (!(ms > 0) || !(targetMs > 0)) return s;
  const double desired = std::clamp(s * std::sqrt(targetMs / ms), double(minScale), 1.0);
  // Down as soon as a frame is over budget; up only when clearly under it (no flicker between two
  // sizes); always to a multiple of 0.05.
  const double step = 0.05;
  if (desired < s - step / 2) return float(std::max(double(minScale), std::floor(desired / step) * step));
  if (desired > s + 2 * step) return float(std::min(1.0, std::floor(desired / step) * step));
  return s;
}

void FrameBudget::declare(ParamRegistry& r) {
  r.addChoice("budget.mode", &mode_, {"auto", "off", "always"},
              "interactive frame budget: auto on software renderers, off, or always (to try it)");
  r.add("budget.fps", &fps_, 1.0f, 1000.0f, "the frame rate the render scale is chosen to hold");
  r.add("budget.min_scale", &minScale_, 0.1f, 1.0f, "the smallest render scale the budget may pick");
}

void FrameBudget::setAllowed(bool windowed, bool softwareRenderer, bool fullResolutionFrame) {
  software_ = softwareRenderer;
  allowed_ = windowed && !fullResolutionFrame && (mode_ == Mode::Always || (mode_ == Mode::Auto && softwareRenderer));
}

unsigned FrameBudget::begin(unsigned windowFbo, int width, int height, int& w, int& h) {
  active_ = allowed_ && scale_ < 1.0f;
  w = width;
  h = height;
  if (!active_) return windowFbo;
  w = std::max(16, int(std::lround(width * scale_)));
  h = std::max(16, int(std::lround(height * scale_)));
  if (target_.width != w || target_.height != h) target_ = gl::makeRenderTarget(w, h, "frame budget");
  return target_.fbo.id();
}

void FrameBudget::end(unsigned windowFbo, int width, int height) {
  if (!active_) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.fbo.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, windowFbo);
  glBlitFramebuffer(0, 0, target_.width, target_.height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, windowFbo);
}

void FrameBudget::record(double frameMs) {
  if (!allowed_) {
    msAvg_ = 0;
    return;
  }
  // The first frames compile shaders and upload the scene: they say nothing about the budget.
  if (++frames_ <= 2) return;
  msAvg_ = msAvg_ == 0 ? frameMs : 0.7 * msAvg_ + 0.3 * frameMs;
  // Aimed 10 % under the budget: frame times scatter around their mean, and a scale that only just
  // holds the mean drops below the frame rate every other frame (measured: 13.3 fps for a 15 fps
  // budget in lesson 05).
  constexpr double kHeadroom = 0.9;
  const float next = nextRenderScale(scale_, msAvg_, kHeadroom * 1000.0 / fps_, std::min(minScale_, 1.0f));
  if (next != scale_) {
    scale_ = next;
    msAvg_ = 0;  // frames at the old scale say nothing about the new one
  }
}

std::string FrameBudget::label() const {
  if (!active_) return "";
  char buf[80];
  std::snprintf(buf, sizeof buf, "render scale %.2f (%s)", scale_, software_ ? "software renderer" : "frame budget");
  return buf;
}

}  // namespace shadowlab

#pragma once
// The god view: the lesson rendered again from a camera outside the scene, into an inset in the
// corner of the frame, with the viewer's frustum and the lesson's debug shapes (DebugDraw) drawn
// in: frusta, light cones, receiver bounds, and later the post-projective unit cube.
#include <functional>

#include "app/debug_draw.hpp"
#include "app/measurement.hpp"
#include "app/lesson.hpp"
#include "core/camera.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"

namespace shadowlab {

class GodView {
 public:
  void declare(ParamRegistry& params);
  bool enabled() const { return enabled_; }
  // Renders the inset into `frame`'s framebuffer. `renderLesson` draws the lesson for a FrameInfo.
  // Frames the scene (`scene`: its bounds, with the viewer's eye; without it, the shapes' extent).
  void draw(const FrameInfo& frame, const OrbitCamera& viewer, const DebugDraw& shapes, const Aabb* scene,
            const std::function<void(const FrameInfo&)>& renderLesson);
  // What the god view's colours mean: the viewer's frustum, then the shapes the lesson named.
  Legend legend(const DebugDraw& shapes) const;
  // The whole of it for a lesson's frame: the lesson drawn again from outside (untimed), its inset
  // and legend reported to the lesson (the UI keeps clear of them), the scene framed when measurable.
  void show(FrameInfo& frame, Lesson& lesson, bool measurable);
  // Where draw() puts the inset in a frame of this size (bottom right).
  Inset inset(int frameWidth, int frameHeight) const;

 private:
  bool enabled_ = false;
  float size_ = 0.4f;      // fraction of the frame's width
  float distance_ = 1.0f;  // times the distance at which their bounding sphere just fits: all of it in view
  float yaw_ = 0.9f;       // radians around the viewer's yaw
  gl::RenderTarget target_;
  LineRenderer lines_{"god view lines"};
};

}  // namespace shadowlab

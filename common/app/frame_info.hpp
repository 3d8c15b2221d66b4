#pragma once
// What a lesson's update() and render() are told about the frame: its size, time, target and the
// camera to draw with (common/app/lesson.hpp; the measurement keeps a frame's to draw it again).
#include <glm/glm.hpp>

namespace shadowlab {

struct FrameInfo {
  int index = 0;
  double time = 0, dt = 0;  // seconds; headless runs use a fixed dt so frames are reproducible
  int width = 0, height = 0;
  float renderScale = 1.0f;  // width and height over the window's: below 1 while the frame budget scales
  unsigned framebuffer = 0;  // draw here (not necessarily 0)
  int measureLight = -1;     // pass to the scene shader's uMeasureLight (shaders/common/measure.glsl)
  // The camera to DRAW with: the lesson's camera, or the god view's camera outside the scene.
  // Shadow techniques fit themselves to `Lesson::camera` (the viewer), never to these, so the god
  // view shows the very shadows the viewer sees.
  glm::mat4 view{1.0f}, projection{1.0f};
  glm::vec3 eye{0.0f};
  bool godView = false;
};

}  // namespace shadowlab

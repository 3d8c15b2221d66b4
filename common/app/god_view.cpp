#include "app/god_view.hpp"

#include <algorithm>

#include "gl/gl.hpp"

namespace shadowlab {

void GodView::declare(ParamRegistry& r) {
  r.add("view.god", &enabled_, "a second camera outside the scene: the view frustum, light frusta and cones, bounds")
      .hotkey = "O";
  r.add("view.god_size", &size_, 0.2f, 1.0f, "the god view inset's width, as a fraction of the frame");
  r.add(
      "view.god_distance", &distance_, 0.3f, 10.0f,
      "how far out the god camera stands: 1 fits the bounding sphere of the scene, the lights' shapes and the viewer");
  r.add("view.god_yaw", &yaw_, -3.2f, 3.2f, "the god camera's angle around the scene, relative to the viewer");
}

Inset GodView::inset(int frameWidth, int frameHeight) const {
  const int w = std::max(16, int(float(frameWidth) * size_));
  const int h = std::max(16, int(float(w) * float(frameHeight) / float(frameWidth)));
  return {"god view inset", frameWidth - w - 8, 8, w, h};
}

namespace {
constexpr glm::vec4 kViewerColour{1, 1, 1, 1};  // white: the lights' colours are warm and cool
}

Legend GodView::legend(const DebugDraw& shapes) const {
  Legend l{"god view", {{glm::vec3(kViewerColour), "the viewer's frustum"}}};
  for (const DebugDraw::Name& n : shapes.names()) l.entries.push_back({glm::vec3(n.color), n.meaning});
  return l;
}

void GodView::draw(const FrameInfo& frame, const OrbitCamera& viewer, const DebugDraw& shapes, const Aabb* scene,
                   const std::function<void(const FrameInfo&)>& renderLesson) {
  const Inset corner = inset(frame.width, frame.height);
  const int w = corner.width, h = corner.height;
  if (target_.width != w || target_.height != h) target_ = gl::makeRenderTarget(w, h, "god view");
  lines_.build();

  // Frame the scene and the viewer's eye: the scene fills the inset (framing every shape, a far
  // light frustum shrank the scene to some 100x50 px of it); without a scene, what the shapes span.
  // The viewer's own frustum reaches its far plane and would shrink everything else to a dot.
  glm::vec3 lo = viewer.position(), hi = lo;
  if (scene && !scene->empty()) {
    lo = glm::min(lo, scene->min);
    hi = glm::max(hi, scene->max);
  } else {
    for (const auto& l : shapes.lines()) {
      lo = glm::min(lo, glm::min(l.a, l.b));
      hi = glm::max(hi, glm::max(l.a, l.b));
    }
  }
  OrbitCamera from = viewer;
  from.yaw = viewer.yaw + yaw_;
  from.pitch = std::max(viewer.pitch, 0.6f);
  const OrbitCamera god = frameBox(from, lo, hi, float(w) / float(h), distance_);
  FrameInfo g = frame;
  g.framebuffer = target_.fbo.id();
  g.width = w;
  g.height = h;
  g.view = god.view();
  g.projection = god.projection(float(w) / float(h));
  g.eye = god.position();
  g.godView = true;
  g.measureLight = -1;
  glBindFramebuffer(GL_FRAMEBUFFER, g.framebuffer);
  glViewport(0, 0, w, h);
  renderLesson(g);

  // The viewer's frustum, then the lesson's shapes.
  DebugDraw all = shapes;
  all.frustum(viewer.projection(float(frame.width) / float(frame.height)) * viewer.view(), kViewerColour);
  glBindFramebuffer(GL_FRAMEBUFFER, g.framebuffer);
  glViewport(0, 0, w, h);
  lines_.draw(all.lines(), g.projection * g.view, true, LineRenderer::projectorWidth(frame.height));

  // Into the bottom-right corner of the frame, with a thin frame around it.
  const int x0 = corner.x, y0 = corner.y;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.framebuffer);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0 - 2, y0 - 2, w + 4, h + 4);
  glClearColor(0.9f, 0.9f, 0.9f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, g.framebuffer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBlitFramebuffer(0, 0, w, h, x0, y0, x0 + w, y0 + h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
}

void GodView::show(FrameInfo& frame, Lesson& lesson, bool measurable) {
  lesson.timers.setEnabled(false);
  const MeasureSource source = measurable ? lesson.measureSource() : MeasureSource{};
  const Aabb bounds = source.scene ? source.scene->bounds() : Aabb{};
  draw(frame, lesson.camera, lesson.debug, source.scene ? &bounds : nullptr,
       [&](const FrameInfo& g) { lesson.render(g); });
  lesson.insets.push_back(inset(frame.width, frame.height));
  lesson.legends.push_back(legend(lesson.debug));
  lesson.timers.setEnabled(true);
  glViewport(0, 0, frame.width, frame.height);
}

}  // namespace shadowlab

#include "technique/shadow_lesson.hpp"

namespace shadowlab::tech {

void ShadowLesson::applyPathLight(const glm::vec3& position, const glm::vec3& direction) {
  const std::span<Light> l = lights();
  if (!pathMovesLight_ || l.empty()) return;
  l[0].position = position;
  l[0].direction = direction;
}

void ShadowLesson::shadowPasses(const ShadowContext& c, ShadowTechnique& technique, bool subject,
                                const std::function<void()>& stages) {
  if (subject && !c.frame.godView) {
    stages();
    technique.pushShapes(c);
  } else {
    technique.renderShadows(c);
  }
  if (!c.frame.godView) counters = technique.stats().counters();
}

void ShadowLesson::drawLit(const ShadowContext& c, ShadowTechnique& technique, const LitSettings& lit) {
  if (!c.frame.godView) {
    litTechnique_ = &technique;
    litSettings_ = lit;
  }
  if (technique.ownsLitPass()) {
    technique.renderLit(c, lit);
    return;
  }
  auto t = scope("scene");
  clearAndDrawLit(c, technique, lit);
}

void ShadowLesson::clearAndDrawLit(const ShadowContext& c, ShadowTechnique& technique, const LitSettings& lit) {
  glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lit_.draw(c, technique, lit);
}

bool ShadowLesson::redrawLit(const FrameInfo& frame) {
  if (!litTechnique_) return false;
  const ShadowContext c = context(frame);
  glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
  glViewport(0, 0, frame.width, frame.height);
  if (litTechnique_->ownsLitPass()) litTechnique_->renderLit(c, litSettings_);
  else clearAndDrawLit(c, *litTechnique_, litSettings_);
  return true;
}

}  // namespace shadowlab::tech

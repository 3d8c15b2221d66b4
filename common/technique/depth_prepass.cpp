#include "technique/depth_prepass.hpp"

namespace shadowlab::tech {

void DepthPrepass::begin(const SceneCache& scene, const glm::mat4& viewProj) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // 0 wherever a surface is (no clear needed)
  pass_.draw(scene, viewProj, {}, {.alphaTest = true, .cullFront = false, .allObjects = true, .alphaLevel0 = false});
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Shade where the depth is the nearest surface's, once: the first fragment sets the stencil to 1.
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
}

void DepthPrepass::end() {
  glDisable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
}

}  // namespace shadowlab::tech

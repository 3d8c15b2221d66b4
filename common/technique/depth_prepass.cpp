#include "technique/depth_prepass.hpp"

#include <algorithm>

#include "algorithms/shadow_math.hpp"

namespace shadowlab::tech {

void DepthPrepass::begin(const SceneCache& scene, const glm::mat4& viewProj, bool draw) {
  // Objects wholly outside the view draw no fragment, but llvmpipe still transforms, clips and
  // bins every vertex of them, in this pass and in the shading pass.
  const std::span<const Aabb> boxes = scene.boxes();
  inView_.assign(boxes.size(), 1);
  culled_ = 0;
  sorted_ = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (shadow::boxOutsideClip(viewProj, boxes[i])) inView_[i] = 0, ++culled_;
    else if (scene.gpu().meshes[scene.scene().objects[i].mesh].viewOrders) ++sorted_;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (!draw) return;
  // Near to far by the clip w of each box's centre (the eye distance along the view); the depth
  // test's LESS keeps the nearest whatever the order, so the image is the same.
  distance_.resize(boxes.size());
  order_.clear();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    distance_[i] = (viewProj * glm::vec4(boxes[i].center(), 1.0f)).w;
    if (inView_[i]) order_.push_back(std::uint32_t(i));
  }
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return distance_[a] < distance_[b]; });
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  // The stencil starts at 0 by a clear, not by the depth pass writing it: a fragment shader with
  // discard (the alpha-tested cards) that also writes stencil gets its depth test after the shader
  // on llvmpipe (late depth test), so every hidden card fragment would pay the alpha fetch.
  glStencilMask(0xff);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_STENCIL_TEST);
  pass_.draw(scene, viewProj, inView_,
             {.alphaTest = true, .cullFront = false, .allObjects = true, .alphaLevel0 = false, .order = order_});
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_STENCIL_TEST);
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

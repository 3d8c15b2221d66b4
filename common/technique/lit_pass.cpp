#include "technique/lit_pass.hpp"

#include "gl/scene_draw.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

gl::Program& LitPass::program(const ShadowTechnique& t) {
  return variants_.get(t.shaderDefines(), {t.visibilityShader()});
}

std::size_t LitPass::draw(const ShadowContext& c, const ShadowTechnique& t, const LitSettings& s) {
  const gl::Program& p = program(t);
  glEnable(GL_DEPTH_TEST);  // whatever the technique's passes left: the lit pass writes depth
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  p.use();
  p.set("uViewProj", c.frame.projection * c.frame.view);
  p.set("uEye", c.frame.eye);
  p.set("uAmbient", s.ambient);
  p.set("uView", s.view);
  p.set("uMeasureLight", c.frame.measureLight);
  p.set("uTexture", 0);
  gl::setLights(p, c.lights);
  t.bindVisibility(p, 1);
  gl::SceneDrawOptions options;
  options.specular = s.specular;
  options.shininess = s.shininess;
  const std::size_t triangles = gl::drawScene(p, c.scene.scene(), c.scene.gpu(), options);
  t.unbindVisibility(1);
  glActiveTexture(GL_TEXTURE0);
  return triangles;
}

}  // namespace shadowlab::tech

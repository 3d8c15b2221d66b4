#include "technique/lit_pass.hpp"

#include <algorithm>

#include "gl/scene_draw.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

std::vector<std::string> LitPass::lightDefines(std::span<const Light> lights, int view) {
  std::string on, kinds;
  for (std::size_t i = 0; i < std::size_t(kMaxLights); ++i) {  // MAX_LIGHTS entries, the ones past the lesson's off
    const bool used = i < lights.size() && lights[i].enabled;
    on += std::string(i ? ", " : "") + (used ? "true" : "false");
    kinds += std::string(i ? ", " : "") + std::to_string(used ? int(lights[i].kind) : 0);
  }
  return {"LIGHT_COUNT " + std::to_string(lights.size()), "LIGHT_ON " + on, "LIGHT_KINDS " + kinds,
          "VIEW " + std::to_string(view)};
}

gl::Program& LitPass::program(const ShadowContext& c, const ShadowTechnique& t, const LitSettings& s) {
  std::vector<std::string> defines = lightDefines(c.lights, s.view);
  if (s.depthPrepass) defines.push_back("DEPTH_PREPASS 1");
  const std::vector<std::string> own = t.shaderDefines();
  defines.insert(defines.end(), own.begin(), own.end());
  // A technique's own texel Jacobian for the aliasing measurement only in measured frames: on
  // llvmpipe the cascades' cost every frame 14-36 % of the scene pass. (Only then a variant of its
  // own, so other techniques' measured runs compile nothing more.)
  const bool measured =
      c.frame.measureLight >= 0 && std::find(own.begin(), own.end(), "SHADOW_TEXEL_JACOBIAN") != own.end();
  if (measured) defines.push_back("MEASURED_FRAME");
  return variants_.get(defines, {t.visibilityShader()}, measured);
}

std::size_t LitPass::draw(const ShadowContext& c, const ShadowTechnique& t, const LitSettings& s) {
  const gl::Program& p = program(c, t, s);
  glEnable(GL_DEPTH_TEST);  // whatever the technique's passes left: the lit pass writes depth
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (s.depthPrepass) {
    if (!prepassBuilt_) prepassBuilt_ = (prepass_.build(), true);
    prepass_.begin(c.scene, c.frame.projection * c.frame.view);
  }
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
  if (s.depthPrepass) options.filter = [this](std::size_t i) { return prepass_.inView(i); };
  else options.viewer = glm::vec4(c.frame.eye, 1.0f);  // without a pre-pass: nearest triangles first
  const std::size_t triangles = gl::drawScene(p, c.scene.scene(), c.scene.gpu(), options);
  t.unbindVisibility(1);
  glActiveTexture(GL_TEXTURE0);
  if (s.depthPrepass) prepass_.end();
  return triangles;
}

}  // namespace shadowlab::tech

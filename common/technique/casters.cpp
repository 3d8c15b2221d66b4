#include "technique/casters.hpp"

#include "core/view_order.hpp"

namespace shadowlab::tech {

CasterPass::CasterPass(std::string label, std::string vertexShader, std::string viewProjUniform,
                       std::string fragmentShader)
    : viewProjUniform_(std::move(viewProjUniform)) {
  const std::array<const char*, BuildCount> defines = {"OPAQUE_CASTER", "", "ALPHA_LEVEL0"};
  const std::array<const char*, BuildCount> names = {" (opaque casters)", " (alpha test)", " (alpha test, level 0)"};
  for (std::size_t b = 0; b < BuildCount; ++b) {
    std::vector<std::string> d;
    if (*defines[b]) d.emplace_back(defines[b]);
    programs_[b] = std::make_unique<gl::Program>(label + names[b],
                                                 std::vector<std::string>{vertexShader, fragmentShader}, std::move(d));
  }
}

void CasterPass::build() {
  for (auto& p : programs_) p->build();
}

void CasterPass::setUniforms(const std::function<void(const gl::Program&)>& set) const {
  for (const auto& p : programs_) {
    if (!p->valid()) continue;
    p->use();
    set(*p);
  }
}

std::size_t CasterPass::draw(const SceneCache& cache, const glm::mat4& viewProj, std::span<const char> keep,
                             const CasterOptions& o) {
  const Scene& scene = cache.scene();
  for (const auto& p : programs_)
    if (!p->valid()) return 0;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(o.cullFront ? GL_FRONT : GL_BACK);
  std::size_t triangles = 0;
  int current = -1;
  unsigned prepared = 0;  // the builds whose per-pass uniforms are set
  const std::size_t count = o.order.empty() ? scene.objects.size() : o.order.size();
  const std::optional<glm::vec4> viewer = o.viewer ? o.viewer
                                          : o.cull ? std::optional(viewerOf(viewProj))
                                                   : std::nullopt;
  for (std::size_t n = 0; n < count; ++n) {
    const std::size_t i = o.order.empty() ? n : o.order[n];
    const SceneObject& object = scene.objects[i];
    if ((!object.castsShadow && !o.allObjects) || (!keep.empty() && !keep[i])) continue;
    const Material& m = scene.materials[object.material];
    const GLuint texture = cache.gpu().materialTextures[object.material].id();
    const bool alpha = o.alphaTest && texture != 0 && m.alphaCutoff > 0.0f;
    const int b = !alpha ? Opaque : o.alphaLevel0 ? AlphaLevel0 : AlphaMip;
    const gl::Program& program = *programs_[std::size_t(b)];
    if (b != current) {
      program.use();
      current = b;
      if (!(prepared & (1u << b))) {
        program.set(viewProjUniform_.c_str(), viewProj);
        program.set("uTexture", 0);
        prepared |= 1u << b;
      }
    }
    const GLuint world = o.worldVertexArray ? o.worldVertexArray(i) : 0;
    program.set("uModel", world ? glm::mat4(1.0f) : object.model);
    if (alpha) {
      program.set("uAlphaCutoff", m.alphaCutoff);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, texture);
    }
    (m.twoSided || !o.cull) ? glDisable(GL_CULL_FACE) : glEnable(GL_CULL_FACE);
    const gl::GpuMesh& mesh = cache.gpu().meshes[object.mesh];
    if (world) {
      glBindVertexArray(world);
      glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
      gl::countDraws();
    } else {
      mesh.draw(viewer ? mesh.orderFor(object.model, *viewer) : -1);
    }
    triangles += scene.meshes[object.mesh].triangleCount();
  }
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  return triangles;
}

}  // namespace shadowlab::tech

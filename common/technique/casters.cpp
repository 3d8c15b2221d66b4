#include "technique/casters.hpp"

namespace shadowlab::tech {

std::size_t CasterPass::draw(const SceneCache& cache, const glm::mat4& viewProj, std::span<const char> keep,
                             const CasterOptions& o) {
  const Scene& scene = cache.scene();
  if (!program_.valid()) return 0;
  program_.use();
  program_.set(viewProjUniform_.c_str(), viewProj);
  program_.set("uAlphaTest", o.alphaTest);
  program_.set("uAlphaLevel0", o.alphaLevel0);
  program_.set("uTexture", 0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(o.cullFront ? GL_FRONT : GL_BACK);
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if ((!object.castsShadow && !o.allObjects) || (!keep.empty() && !keep[i])) continue;
    const Material& m = scene.materials[object.material];
    const GLuint texture = cache.gpu().materialTextures[object.material].id();
    const GLuint world = o.worldVertexArray ? o.worldVertexArray(i) : 0;
    program_.set("uModel", world ? glm::mat4(1.0f) : object.model);
    program_.set("uAlphaCutoff", m.alphaCutoff);
    program_.set("uUseTexture", texture != 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    (m.twoSided || !o.cull) ? glDisable(GL_CULL_FACE) : glEnable(GL_CULL_FACE);
    const gl::GpuMesh& mesh = cache.gpu().meshes[object.mesh];
    if (world) {
      glBindVertexArray(world);
      glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
      gl::countDraws();
    } else {
      mesh.draw();
    }
    triangles += scene.meshes[object.mesh].triangleCount();
  }
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  return triangles;
}

}  // namespace shadowlab::tech

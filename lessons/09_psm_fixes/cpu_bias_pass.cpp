#include "cpu_bias_pass.hpp"

#include <string>

#include "algorithms/psm/bias.hpp"
#include "gl/mesh_gpu.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

ProjectiveMapSet::WorldBias CpuBiasPass::with(Bias bias) {
  return [this, bias = std::move(bias)](const ProjectiveMapSet::BiasedDraw& d) { return draw(bias, d); };
}

std::size_t CpuBiasPass::draw(const Bias& bias, const ProjectiveMapSet::BiasedDraw& d) {
  const Scene& scene = d.c.scene.scene();
  // 1. Move every vertex of every kept caster: P + L (a + b L_texel), L from the light through P.
  moved_.clear();
  std::vector<std::size_t> first(scene.objects.size(), 0);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.castsShadow || (!d.keep.empty() && !d.keep[i])) continue;
    first[i] = moved_.size();
    for (const glm::vec3& v : scene.meshes[o.mesh].positions) {
      const glm::dvec3 p(o.model * glm::vec4(v, 1.0f));
      const glm::dvec3 l = psm::directionFromLight(d.worldLight, p);
      moved_.push_back(glm::vec3(bias(d.worldToClip, p, l, d.a, d.b, double(d.side))));
    }
  }
  // 2. Upload them as world positions (the model matrix is already applied).
  if (!vertices_) vertices_ = gl::makeBuffer(GL_ARRAY_BUFFER, "lesson 09: CPU-biased vertices");
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(moved_.size() * sizeof(glm::vec3)), moved_.data(), GL_STREAM_DRAW);
  // 3. Each object's vertex array: its moved positions, its mesh's own uvs (for the alpha test) and
  //    indices; the depth pass draws it with the world -> map matrix alone.
  vaos_.resize(scene.objects.size());
  CasterOptions options = d.options;
  options.worldVertexArray = [&](std::size_t i) -> GLuint {
    const gl::GpuMesh& mesh = d.c.scene.gpu().meshes[scene.objects[i].mesh];
    if (!vaos_[i]) vaos_[i] = gl::makeVertexArray("lesson 09: CPU-biased object " + std::to_string(i));
    glBindVertexArray(vaos_[i].id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3),
                          reinterpret_cast<void*>(first[i] * sizeof(glm::vec3)));
    glBindBuffer(GL_ARRAY_BUFFER, mesh.vertices.id());  // the mesh's interleaved uvs (gl/mesh_gpu.cpp)
    glEnableVertexAttribArray(gl::kUv);
    glVertexAttribPointer(gl::kUv, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                          reinterpret_cast<void*>(6 * sizeof(float)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.id());
    return vaos_[i].id();
  };
  casters_.setUniforms([&](const gl::Program& p) {
    p.set("uWorldBias", false);  // moved above
    p.set("uSlopeOffset", d.slopeOffset);
  });
  const std::size_t triangles = casters_.draw(d.c.scene, glm::mat4(d.worldToClip), d.keep, options);
  glBindVertexArray(0);
  return triangles;
}

}  // namespace shadowlab::tech

#include "gl/mesh_gpu.hpp"

#include <cstddef>

#include "gl/texture.hpp"

namespace shadowlab::gl {
namespace {
struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 uv;
};
}  // namespace

GpuMesh uploadMesh(const Mesh& mesh, const std::string& label) {
  std::vector<Vertex> interleaved(mesh.positions.size());
  for (std::size_t i = 0; i < interleaved.size(); ++i) {
    interleaved[i].position = mesh.positions[i];
    interleaved[i].normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
    interleaved[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0);
  }
  GpuMesh gpu;
  gpu.vao = makeVertexArray(label);
  gpu.vertices = makeBuffer(GL_ARRAY_BUFFER, label + ".vertices");
  gpu.indices = makeBuffer(GL_ELEMENT_ARRAY_BUFFER, label + ".indices");
  gpu.indexCount = GLsizei(mesh.indices.size());
  glBindVertexArray(gpu.vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(Vertex)), interleaved.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(kPosition);
  glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(kNormal);
  glVertexAttribPointer(kNormal, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(kUv);
  glVertexAttribPointer(kUv, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, uv)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return gpu;
}

void GpuMesh::draw() const {
  glBindVertexArray(vao.id());
  glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  countDraws();
}

GpuScene uploadScene(const Scene& scene, const std::string& label) {
  GpuScene gpu;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    gpu.meshes.push_back(uploadMesh(scene.meshes[i], label + ".mesh" + std::to_string(i)));
  for (const auto& material : scene.materials)
    gpu.materialTextures.push_back(material.texture.empty() ? Texture() : loadTexture(material.texture));
  return gpu;
}

}  // namespace shadowlab::gl

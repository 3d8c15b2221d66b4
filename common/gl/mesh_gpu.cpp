#include "gl/mesh_gpu.hpp"

#include <cstddef>

#include "core/view_order.hpp"
#include "gl/texture.hpp"

namespace shadowlab::gl {
namespace {
struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 uv;
};
}  // namespace

GpuMesh uploadMesh(const Mesh& mesh, const std::string& label, bool viewOrders) {
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
  gpu.viewOrders = viewOrders && !mesh.indices.empty();
  gpu.centre = mesh.positions.empty() ? glm::vec3(0.0f) : mesh.bounds().center();
  std::vector<std::uint32_t> withOrders;  // the mesh's own indices, then every view order
  if (gpu.viewOrders) {
    withOrders = mesh.indices;
    const std::vector<std::uint32_t> orders = shadowlab::viewOrders(mesh);
    withOrders.insert(withOrders.end(), orders.begin(), orders.end());
  }
  const std::vector<std::uint32_t>& indices = gpu.viewOrders ? withOrders : mesh.indices;
  glBindVertexArray(gpu.vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(Vertex)), interleaved.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
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

void GpuMesh::draw(int order) const {
  glBindVertexArray(vao.id());
  const std::size_t first = viewOrders && order >= 0 ? std::size_t(order + 1) * std::size_t(indexCount) : 0;
  glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(first * sizeof(std::uint32_t)));
  countDraws();
}

int GpuMesh::orderFor(const glm::mat4& model, const glm::vec4& viewer) const {
  if (!viewOrders) return -1;
  const glm::vec4 local = glm::inverse(model) * viewer;
  return viewOrderFor(viewer.w != 0.0f ? glm::vec3(local) / local.w - centre : glm::vec3(local));
}

GpuScene uploadScene(const Scene& scene, const std::string& label) {
  GpuScene gpu;
  // Front-to-back orders for the meshes that hide themselves many times over: the alpha-tested ones
  // (their depth pass and lit shader can discard, so only their early depth test saves the work) of
  // many triangles (a crown of leaf cards, not a fence panel).
  std::vector<char> sorted(scene.meshes.size(), 0);
  for (const SceneObject& o : scene.objects) {
    const Material& m = scene.materials[o.material];
    if (m.alphaCutoff > 0.0f && !m.texture.empty() && scene.meshes[o.mesh].triangleCount() >= kViewOrderMinTriangles)
      sorted[o.mesh] = 1;
  }
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    gpu.meshes.push_back(uploadMesh(scene.meshes[i], label + ".mesh" + std::to_string(i), sorted[i] != 0));
  for (const auto& material : scene.materials)
    gpu.materialTextures.push_back(material.texture.empty() ? Texture() : loadTexture(material.texture));
  return gpu;
}

}  // namespace shadowlab::gl

#pragma once
// CPU meshes (core/mesh) uploaded once into GPU buffers. Attribute locations are fixed across the
// course so every shader agrees: 0 position, 1 normal, 2 uv.
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "gl/objects.hpp"

namespace shadowlab::gl {

enum AttributeLocation : GLuint { kPosition = 0, kNormal = 1, kUv = 2 };

struct GpuMesh {
  VertexArray vao;
  Buffer vertices, indices;
  GLsizei indexCount = 0;
  // With view orders (core/view_order): after the mesh's own indices, its triangles sorted front to
  // back for each of viewOrderDirections(), so a viewer's fragments meet the depth test nearest first.
  bool viewOrders = false;
  glm::vec3 centre{0.0f};  // of the mesh's bounds, in its own space: where a viewer's direction starts
  // glDrawElements of every triangle, in order `order` (viewOrderFor; -1 or no view orders: the
  // mesh's own).
  void draw(int order = -1) const;
  // The order for a viewer at `viewer` (w = 1, world space) or from direction `viewer` (w = 0: toward
  // the viewer) when the mesh is drawn with `model`; -1 without view orders.
  int orderFor(const glm::mat4& model, const glm::vec4& viewer) const;
};
// viewOrders: upload the front-to-back orders too (26 more copies of the indices).
GpuMesh uploadMesh(const Mesh& mesh, const std::string& label, bool viewOrders = false);

// A scene's meshes and material textures on the GPU; objects are drawn by the lesson, which owns
// the per-object uniforms. Meshes of alpha-tested materials with at least kViewOrderMinTriangles
// triangles get view orders.
inline constexpr std::size_t kViewOrderMinTriangles = 64;
struct GpuScene {
  std::vector<GpuMesh> meshes;
  std::vector<Texture> materialTextures;  // one per material; 0 when it has none
};
// Throws std::runtime_error naming a texture path that cannot be read.
GpuScene uploadScene(const Scene& scene, const std::string& label);

}  // namespace shadowlab::gl

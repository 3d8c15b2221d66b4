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
  void draw() const;  // glDrawElements of every triangle
};
GpuMesh uploadMesh(const Mesh& mesh, const std::string& label);

// A scene's meshes and material textures on the GPU; objects are drawn by the lesson, which owns
// the per-object uniforms.
struct GpuScene {
  std::vector<GpuMesh> meshes;
  std::vector<Texture> materialTextures;  // one per material; 0 when it has none
};
// Throws std::runtime_error naming a texture path that cannot be read.
GpuScene uploadScene(const Scene& scene, const std::string& label);

}  // namespace shadowlab::gl

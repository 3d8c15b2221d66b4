#pragma once
// Scenes: meshes, materials and placed objects, all on the CPU. Procedural scenes are deterministic
// from a seed (see scene_gen.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"

namespace shadowlab {

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};
  std::string texture;       // file name under textures/ (e.g. "checker.png"); empty: none
  float alphaCutoff = 0.0f;  // > 0: alpha-tested (texels with alpha below it are holes)
  float specular = 0.25f;    // k_s
  float shininess = 32.0f;   // Blinn-Phong exponent
  bool twoSided = false;     // leaf cards: lit from both sides, never back-face culled
};

struct SceneObject {
  std::string name;
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t material = 0;  // index into Scene::materials
  glm::mat4 model{1.0f};
  bool castsShadow = true;
  bool receivesShadow = true;
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<SceneObject> objects;

  Aabb bounds() const;  // world-space bounds of every object
  Aabb objectBounds(std::size_t object) const;
  std::size_t triangleCount() const;  // world triangles (instances counted each time)
  std::uint32_t addMesh(Mesh mesh);
  std::uint32_t addMaterial(Material material);
  void addObject(SceneObject object);
};

}  // namespace shadowlab

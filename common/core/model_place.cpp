// A loaded model on the course's ground and in the camera's view, and the process's current model
// (core/model_file.hpp): no importer here, so the browser build, which has none, shares it.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "core/mesh_gen.hpp"
#include "core/model_file.hpp"

namespace shadowlab {

ModelFraming frameModel(const Scene& placed, float fovY) {
  Aabb box;
  for (std::size_t i = 1; i < placed.objects.size(); ++i) box.extend(placed.objectBounds(i));
  if (box.empty()) return {};
  const float radius = std::max(0.5f * glm::length(box.extent()), 1e-3f);
  const float halfAngle = std::atan(0.45f * std::tan(0.5f * fovY));  // the sphere's, seen from the camera
  return {box.center(), radius / std::sin(halfAngle)};
}

Scene placeOnGround(const ModelFile& model, float size, float groundSize) {
  Scene scene;
  scene.name = "model " + model.scene.name;
  const Aabb box = model.scene.bounds();
  const glm::vec3 extent = box.extent();
  const float largest = std::max({extent.x, extent.y, extent.z, 1e-6f});
  const float scale = size / largest;
  // Scale about the box's bottom centre, which lands on the origin.
  const glm::vec3 base(box.center().x, box.min.y, box.center().z);
  const glm::mat4 place = glm::scale(glm::mat4(1.0f), glm::vec3(scale)) * glm::translate(glm::mat4(1.0f), -base);
  Material ground;
  ground.name = "checker ground";
  ground.albedo = glm::vec3(0.85f);
  ground.texture = "checker.png";
  ground.specular = 0.1f;
  ground.shininess = 16.0f;
  const std::uint32_t groundMaterial = scene.addMaterial(ground);
  SceneObject plane;
  plane.name = "ground";
  plane.mesh = scene.addMesh(makePlane(groundSize, 32, groundSize / 3.0f));
  plane.material = groundMaterial;
  plane.castsShadow = false;
  scene.addObject(plane);
  const std::uint32_t meshBase = std::uint32_t(scene.meshes.size()),
                      materialBase = std::uint32_t(scene.materials.size());
  for (const Mesh& m : model.scene.meshes) scene.addMesh(m);
  for (const Material& m : model.scene.materials) scene.addMaterial(m);
  for (SceneObject o : model.scene.objects) {
    o.mesh += meshBase;
    o.material += materialBase;
    o.model = place * o.model;
    scene.addObject(std::move(o));
  }
  return scene;
}

namespace {
struct Current {
  std::unique_ptr<ModelFile> file;
  std::uint64_t generation = 0;
};
Current& current() {
  static Current c;
  return c;
}
}  // namespace

const ModelFile& loadCurrentModel(const std::string& path) {
  auto file = std::make_unique<ModelFile>(loadModelFile(path));
  current().file = std::move(file);
  ++current().generation;
  return *current().file;
}

const ModelFile* currentModel() { return current().file.get(); }
std::uint64_t currentModelGeneration() { return current().generation; }

}  // namespace shadowlab

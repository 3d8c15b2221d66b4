#include "core/scene.hpp"

#include <stdexcept>

namespace shadowlab {

namespace {
Aabb transformBox(const Aabb& box, const glm::mat4& model) {
  Aabb out;
  if (box.empty()) return out;
  // The eight corners bound the transformed box exactly for affine maps.
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner{(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                           (i & 4) ? box.max.z : box.min.z};
    out.extend(glm::vec3(model * glm::vec4(corner, 1.0f)));
  }
  return out;
}
}  // namespace

Aabb Scene::objectBounds(std::size_t object) const {
  if (object >= objects.size())
    throw std::out_of_range("Scene::objectBounds: object " + std::to_string(object) + " of " +
                            std::to_string(objects.size()));
  const SceneObject& o = objects[object];
  if (o.mesh >= meshes.size())
    throw std::out_of_range("Scene::objectBounds: object '" + o.name + "' names mesh " + std::to_string(o.mesh) +
                            " of " + std::to_string(meshes.size()));
  return transformBox(meshes[o.mesh].bounds(), o.model);
}

Aabb Scene::bounds() const {
  // Mesh bounds are computed once per mesh, not once per instance: cities share one block mesh.
  std::vector<Aabb> meshBounds;
  meshBounds.reserve(meshes.size());
  for (const Mesh& m : meshes) meshBounds.push_back(m.bounds());
  Aabb box;
  for (const SceneObject& o : objects)
    if (o.mesh < meshBounds.size()) box.extend(transformBox(meshBounds[o.mesh], o.model));
  return box;
}

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const SceneObject& o : objects)
    if (o.mesh < meshes.size()) n += meshes[o.mesh].triangleCount();
  return n;
}

std::uint32_t Scene::addMesh(Mesh mesh) {
  meshes.push_back(std::move(mesh));
  return static_cast<std::uint32_t>(meshes.size() - 1);
}

std::uint32_t Scene::addMaterial(Material material) {
  materials.push_back(std::move(material));
  return static_cast<std::uint32_t>(materials.size() - 1);
}

void Scene::addObject(SceneObject object) { objects.push_back(std::move(object)); }

}  // namespace shadowlab

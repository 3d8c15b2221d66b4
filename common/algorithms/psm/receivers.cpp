#include "algorithms/psm/receivers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

namespace {

// One large object's triangles binned by centroid into cells of side `cell`, appended as boxes.
void binTriangles(const Mesh& mesh, const glm::mat4& model, const Aabb& bounds, float cell, std::vector<Aabb>& out) {
  const glm::vec3 origin = bounds.min;
  const glm::ivec3 count = glm::max(glm::ivec3(glm::ceil(bounds.extent() / cell)), glm::ivec3(1));
  std::map<int, Aabb> cells;  // sorted: the output order does not depend on hashing
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::vec3 v[3];
    for (int k = 0; k < 3; ++k) v[k] = glm::vec3(model * glm::vec4(mesh.positions[mesh.indices[t + k]], 1.0f));
    const glm::vec3 centroid = (v[0] + v[1] + v[2]) / 3.0f;
    const glm::ivec3 c = glm::clamp(glm::ivec3((centroid - origin) / cell), glm::ivec3(0), count - 1);
    Aabb& box = cells[(c.z * count.y + c.y) * count.x + c.x];
    for (const glm::vec3& p : v) box.extend(p);
  }
  for (const auto& [key, box] : cells)
    if (box.min != box.max) out.push_back(box);  // a degenerate triangle alone is no volume
}

}  // namespace

std::vector<Aabb> receiverVolumes(const Scene& scene, int tiles) {
  if (tiles > 256) throw std::invalid_argument("receiver tiles = " + std::to_string(tiles) + " is above 256");
  std::vector<Aabb> out;
  const glm::vec3 extent = scene.bounds().extent();
  const float cell = std::max({extent.x, extent.y, extent.z}) / float(std::max(tiles, 1));
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.receivesShadow) continue;
    const Aabb box = scene.objectBounds(i);
    if (box.empty()) continue;
    const glm::vec3 e = box.extent();
    if (tiles <= 1 || std::max({e.x, e.y, e.z}) <= cell) {
      if (box.min != box.max) out.push_back(box);
      continue;
    }
    binTriangles(scene.meshes[o.mesh], o.model, box, cell, out);
  }
  return out;
}

bool mayShadowFrustum(const Aabb& box, const Frustum& frustum, const glm::dvec4& light) {
  const glm::dvec3 lo(box.min), hi(box.max);
  for (const Plane& p : frustum.planes) {
    // The box corner farthest along the inward normal: if even it is outside, all of the box is.
    const glm::dvec3 far(p.normal.x >= 0 ? hi.x : lo.x, p.normal.y >= 0 ? hi.y : lo.y, p.normal.z >= 0 ? hi.z : lo.z);
    if (p.distance(far) >= 0.0) continue;
    const double lightSide = glm::dot(p.normal, glm::dvec3(light)) + p.offset * light.w;
    if (lightSide >= 0.0) return false;
  }
  return true;
}

int potentialCasters(std::span<const Aabb> boxes, std::span<const char> casts, const Frustum& frustum,
                     const glm::dvec4& light, std::vector<char>& out) {
  if (casts.size() != boxes.size())
    throw std::invalid_argument("potentialCasters: " + std::to_string(casts.size()) + " caster flags for " +
                                std::to_string(boxes.size()) + " boxes");
  out.assign(boxes.size(), 0);
  int kept = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    out[i] = casts[i] && !boxes[i].empty() && mayShadowFrustum(boxes[i], frustum, light);
    kept += out[i];
  }
  return kept;
}

}  // namespace shadowlab::psm

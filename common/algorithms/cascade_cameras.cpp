#include "algorithms/cascade_cameras.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/psm/cascades.hpp"

namespace shadowlab::shadow {

double cascadeFar(const CascadeViewer& v, const Aabb& b) {
  double deepest = 0.0;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
    deepest = std::max(deepest, -double((v.view * glm::vec4(corner, 1.0f)).z));
  }
  if (deepest <= double(v.nearZ)) return double(v.farZ);
  return std::min(deepest, double(v.farZ));
}

CascadeSet fitCascades(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& v,
                       const CascadeOptions& o) {
  if (o.count < 1 || o.count > 4)
    throw std::invalid_argument("cascade count = " + std::to_string(o.count) + " must be 1..4");
  CascadeSet set;
  const double zFar = o.farZ > 0.0 ? std::min(o.farZ, double(v.farZ)) : cascadeFar(v, scene.bounds);
  set.splits = psm::cascadeSplits(double(v.nearZ), std::max(zFar, double(v.nearZ) * 1.001), o.count, o.lambda);
  for (int i = 0; i < o.count; ++i) {
    const glm::mat4 slice =
        glm::perspective(v.fovY, v.aspect, float(set.splits[std::size_t(i)]), float(set.splits[std::size_t(i) + 1]));
    set.cameras.push_back(fitDirectional(direction, scene, volumeFromViewProj(slice * v.view), o.fit));
  }
  return set;
}

}  // namespace shadowlab::shadow

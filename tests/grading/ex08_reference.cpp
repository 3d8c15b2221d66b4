// Reference for lesson 08's exercises: forwards to common/algorithms/psm (never a copy).
#include "exercises.hpp"

#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/psm_camera.hpp"

namespace shadowlab::ex08 {

glm::dvec4 postProjectiveLight(const glm::dmat4& viewProj, const glm::dvec4& light) {
  const psm::PostProjectiveLight l = psm::toPostProjective(viewProj, light);
  switch (l.kind) {
    case psm::PostLightKind::InFront: return glm::dvec4(l.position, 1.0);
    case psm::PostLightKind::Behind: return glm::dvec4(l.position, -1.0);
    case psm::PostLightKind::Direction: break;
  }
  return glm::dvec4(l.direction, 0.0);
}

double virtualCameraShift(const glm::dmat4& view, double zNear, const std::vector<glm::dvec3>& casterCorners) {
  return psm::virtualCameraShift(view, zNear, casterCorners);
}

}  // namespace shadowlab::ex08

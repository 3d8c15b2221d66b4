// Reference for lesson 09's exercises: forwards to common/algorithms/psm (never a copy).
#include "exercises.hpp"

#include "algorithms/psm/bias.hpp"
#include "algorithms/psm/cube_faces.hpp"
#include "algorithms/psm/enclosing_cone.hpp"
#include "algorithms/psm/lispsm.hpp"
#include "algorithms/psm/psm_camera.hpp"

namespace shadowlab::ex09 {

glm::dmat4 inverseProjection(double fovY, double aspect, double a) { return psm::inverseProjection(fovY, aspect, a); }

glm::dvec4 smallestEnclosingCone(const std::vector<glm::dvec3>& directions) {
  if (directions.empty()) return glm::dvec4(0.0);
  std::vector<glm::dvec3> copy = directions;
  const psm::Cone c = psm::smallestEnclosingCone(copy);
  return glm::dvec4(c.axis, c.halfAngle);
}

bool cubeFaceVisible(int face, const glm::dvec4& postLight) {
  psm::PostProjectiveLight l;
  if (postLight.w == 0.0) {
    l.kind = psm::PostLightKind::Direction;
    l.direction = glm::normalize(glm::dvec3(postLight));
  } else {
    l.kind = postLight.w > 0.0 ? psm::PostLightKind::InFront : psm::PostLightKind::Behind;
    l.position = glm::dvec3(postLight);
  }
  return psm::cubeFaceVisible(face, l);
}

glm::dvec3 texelSizeBias(const glm::dmat4& worldToClip, const glm::dvec3& p, const glm::dvec3& dirFromLight, double a,
                         double b, double mapSize) {
  const glm::dmat4 K = psm::texelOffsetMatrix(worldToClip, glm::dvec2(mapSize));
  return psm::biasedWorldPoint(p, dirFromLight, a, b, psm::texelWorldSize(K, p));
}

double lispsmOptimalN(double z0, double z1, double gamma) { return psm::lispsmOptimalN(z0, z1, gamma); }

}  // namespace shadowlab::ex09

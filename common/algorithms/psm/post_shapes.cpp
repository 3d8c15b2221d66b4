#include "algorithms/psm/post_shapes.hpp"

#include <cmath>
#include <numbers>

namespace shadowlab::psm {

void PostProjectiveShapes::cross(const glm::dvec3& p, double size, const glm::vec4& colour) {
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 d(0.0);
    d[a] = size;
    segment(p - d, p + d, colour);
  }
}

void PostProjectiveShapes::frustum(const glm::dmat4& clipToPost, const glm::vec4& colour) {
  glm::dvec4 c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = clipToPost * glm::dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
  static constexpr int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                       {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : edges) line(c[e[0]], c[e[1]], colour);
}

void PostProjectiveShapes::cone(const glm::dvec3& apex, const glm::dvec3& axis, double halfAngle, double length,
                                const glm::vec4& colour) {
  const glm::dvec3 u = anyPerpendicular(axis), v = glm::cross(axis, u);
  const double r = length * std::tan(halfAngle), h = length;
  glm::dvec3 previous{};
  for (int k = 0; k <= 32; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 32.0;
    const glm::dvec3 rim = apex + axis * h + (u * std::cos(a) + v * std::sin(a)) * r;
    if (k > 0) segment(previous, rim, colour);
    if (k % 4 == 0 && k < 32) segment(apex, rim, colour);
    previous = rim;
  }
}

void PostProjectiveShapes::light(const PostProjectiveLight& l, const glm::vec4& colour) {
  if (l.kind == PostLightKind::Direction) {
    // Parallel rays through the cube, arriving from infinity toward +direction.
    const glm::dvec3 u = anyPerpendicular(l.direction), v = glm::cross(l.direction, u);
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) {
        const glm::dvec3 p = (u * double(i) + v * double(j)) * 0.8;
        line(glm::dvec4(l.direction, 0.0), glm::dvec4(p - l.direction * 1.8, 1.0), colour);
      }
    return;
  }
  cross(l.position, 0.08, colour);
  const double len = glm::length(l.position);
  if (!(len > 0.0)) return;
  const glm::dvec3 u = l.position / len;  // from the cube's centre toward the light
  if (l.kind == PostLightKind::InFront) {
    segment(l.position, glm::dvec3(0.0), colour);
    return;
  }
  // Behind: its rays leave it away from the cube, pass through infinity and come back from the
  // far side (the inverse projection orders them that way).
  line(glm::dvec4(l.position, 1.0), glm::dvec4(u, 0.0), colour);
  line(glm::dvec4(-u, 0.0), glm::dvec4(-u * 1.8, 1.0), colour);
}

void describePlan(const PsmPlan& plan, const CameraFrustum& real, std::span<const glm::dvec3> points,
                  PostProjectiveShapes& out, std::size_t maxPoints, const PostProjectivePalette& pal) {
  if (plan.shift > 0.0) out.frustum(plan.camera.viewProj * real.invViewProj, pal.realCube);
  for (const PsmMap& m : plan.used()) out.frustum(glm::inverse(m.camera.postToClip), pal.map);
  if (plan.cone.valid && !plan.faces && plan.light.kind != PostLightKind::Direction) {
    double reach = 0.0;
    for (const glm::dvec3& p : points) reach = std::max(reach, glm::dot(p - plan.light.position, plan.cone.axis));
    out.cone(plan.light.position, plan.cone.axis, plan.cone.halfAngle, std::min(reach, 50.0), pal.cone);
  }
  const std::size_t step = points.size() > maxPoints ? (points.size() + maxPoints - 1) / maxPoints : 1;
  for (std::size_t i = 0; i < points.size(); i += step) out.cross(points[i], 0.012, pal.keyPoint);
}

}  // namespace shadowlab::psm

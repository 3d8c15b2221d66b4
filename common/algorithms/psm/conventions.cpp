#include "algorithms/psm/conventions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

namespace {
[[noreturn]] void fail(const std::string& what, double value) {
  throw std::invalid_argument(what + " = " + std::to_string(value) + " is invalid");
}
}  // namespace

glm::dmat4 depthRangeRemap(DepthRange range) {
  glm::dmat4 m(1.0);
  if (range == DepthRange::ZeroToOne) {
    // z' = (z + w) / 2: a clip-space remap, so it commutes with the perspective divide.
    m[2][2] = 0.5;
    m[3][2] = 0.5;
  }
  return m;
}

double depthRangeLow(DepthRange range) { return range == DepthRange::ZeroToOne ? 0.0 : -1.0; }

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(const glm::dvec4& v) { return isFinite(glm::dvec3(v)) && std::isfinite(v.w); }
bool isFinite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!isFinite(m[c])) return false;
  return true;
}
void requireFinite(const glm::dmat4& m, const char* what) {
  if (!isFinite(m)) throw std::invalid_argument(std::string(what) + " is not finite");
}
void requireFinite(const glm::dvec3& v, const char* what) {
  if (!isFinite(v)) throw std::invalid_argument(std::string(what) + " is not finite");
}

glm::dvec4 homogeneousLight(const Light& light) {
  if (light.kind == LightKind::Directional) {
    glm::dvec3 d(light.direction);
    requireFinite(d, "light.direction");
    if (glm::dot(d, d) == 0.0) throw std::invalid_argument("light.direction is the zero vector");
    return glm::dvec4(-glm::normalize(d), 0.0);
  }
  glm::dvec3 p(light.position);
  requireFinite(p, "light.position");
  return glm::dvec4(p, 1.0);
}

PostProjectiveLight toPostProjective(const glm::dmat4& viewProj, const glm::dvec4& light, double directionTolerance) {
  requireFinite(viewProj, "viewProj");
  if (!isFinite(light)) throw std::invalid_argument("light (homogeneous) is not finite");
  if (light == glm::dvec4(0.0)) throw std::invalid_argument("light (homogeneous) is the zero vector");
  PostProjectiveLight out;
  out.homogeneous = viewProj * light;
  const glm::dvec3 xyz(out.homogeneous);
  const double w = out.homogeneous.w;
  const double len = glm::length(xyz);
  if (std::abs(w) <= directionTolerance * len) {
    out.kind = PostLightKind::Direction;
    out.direction = xyz / len;
    return out;
  }
  out.kind = w > 0.0 ? PostLightKind::InFront : PostLightKind::Behind;
  out.position = xyz / w;
  const double pl = glm::length(out.position);
  out.direction = pl > 0.0 ? out.position / pl : glm::dvec3(0.0, 0.0, 1.0);
  return out;
}

glm::dmat4 perspectiveGL(double fovY, double aspect, double zNear, double zFar) {
  if (!std::isfinite(fovY) || fovY <= 0.0 || fovY >= std::numbers::pi) fail("fovY", fovY);
  if (!std::isfinite(aspect) || aspect <= 0.0) fail("aspect", aspect);
  if (!std::isfinite(zNear) || zNear <= 0.0) fail("zNear", zNear);
  if (!std::isfinite(zFar) || zFar <= zNear) fail("zFar", zFar);
  const double t = 1.0 / std::tan(fovY / 2.0);
  glm::dmat4 m(0.0);
  m[0][0] = t / aspect;
  m[1][1] = t;
  m[2][2] = -(zFar + zNear) / (zFar - zNear);
  m[2][3] = -1.0;
  m[3][2] = -2.0 * zFar * zNear / (zFar - zNear);
  return m;
}

CameraFrustum makeCamera(const glm::dmat4& view, double fovY, double aspect, double zNear, double zFar) {
  requireFinite(view, "view");
  CameraFrustum c;
  c.view = view;
  c.projection = perspectiveGL(fovY, aspect, zNear, zFar);
  c.viewProj = c.projection * view;
  c.invViewProj = glm::inverse(c.viewProj);
  requireFinite(c.invViewProj, "inverse(viewProj)");
  c.fovY = fovY;
  c.aspect = aspect;
  c.zNear = zNear;
  c.zFar = zFar;
  return c;
}

glm::dvec3 anyPerpendicular(const glm::dvec3& v) {
  // Cross with the coordinate axis least aligned with v: never near-parallel.
  const glm::dvec3 a = glm::abs(v);
  glm::dvec3 e(0.0);
  if (a.x <= a.y && a.x <= a.z) e.x = 1.0;
  else if (a.y <= a.z) e.y = 1.0;
  else e.z = 1.0;
  return glm::normalize(glm::cross(v, e));
}

glm::dmat4 lookAlong(const glm::dvec3& eye, const glm::dvec3& forward) {
  const glm::dvec3 f = glm::normalize(forward);
  const glm::dvec3 s = anyPerpendicular(f);  // right
  const glm::dvec3 u = glm::cross(s, f);     // up, so (s, u, -f) is right-handed
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][0] = s.y;
  m[2][0] = s.z;
  m[0][1] = u.x;
  m[1][1] = u.y;
  m[2][1] = u.z;
  m[0][2] = -f.x;
  m[1][2] = -f.y;
  m[2][2] = -f.z;
  m[3][0] = -glm::dot(s, eye);
  m[3][1] = -glm::dot(u, eye);
  m[3][2] = glm::dot(f, eye);
  return m;
}

}  // namespace shadowlab::psm

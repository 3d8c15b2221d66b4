#include "algorithms/psm/lispsm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

double lispsmOptimalN(double zn, double zf, double gamma) {
  if (!std::isfinite(zn) || zn <= 0.0) throw std::invalid_argument("zNear = " + std::to_string(zn) + " must be > 0");
  if (!std::isfinite(zf) || zf <= zn) throw std::invalid_argument("zFar = " + std::to_string(zf) + " must be > zNear");
  if (!std::isfinite(gamma)) throw std::invalid_argument("gamma is not finite");
  const double s = std::abs(std::sin(gamma));
  if (s == 0.0) return std::numeric_limits<double>::infinity();
  return (zn + std::sqrt(zn * zf)) / s;
}

namespace {

// Swizzle after the perspective: map x = x, map y = frame z, depth grows along the light (-y).
glm::dmat4 lispsmSwizzle() {
  glm::dmat4 swz(0.0);
  swz[0][0] = 1.0;
  swz[2][1] = 1.0;
  swz[1][2] = -1.0;
  swz[3][3] = 1.0;
  return swz;
}

// The orthographic box [lo, hi] (padded by pad) of the light's frame onto [-1, 1]^3: the uniform
// map LiSPSM falls back on.
glm::dmat4 frameBox(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& pad) {
  glm::dmat4 o(1.0);
  o[0][0] = 2.0 / (hi.x - lo.x + 2 * pad.x);
  o[3][0] = -(hi.x + lo.x) / (hi.x - lo.x + 2 * pad.x);
  o[1][1] = 2.0 / (hi.y - lo.y + 2 * pad.y);
  o[3][1] = -(hi.y + lo.y) / (hi.y - lo.y + 2 * pad.y);
  o[2][2] = 2.0 / (hi.z - lo.z + 2 * pad.z);
  o[3][2] = -(hi.z + lo.z) / (hi.z - lo.z + 2 * pad.z);
  return o;
}

// The perspective looking down -z over the screen box [sMin, sMax], depth from nearD to farD.
glm::dmat4 warpPerspective(const glm::dvec2& sMin, const glm::dvec2& sMax, double nearD, double farD) {
  glm::dmat4 p(0.0);
  p[0][0] = 2.0 / (sMax.x - sMin.x);
  p[2][0] = (sMax.x + sMin.x) / (sMax.x - sMin.x);
  p[1][1] = 2.0 / (sMax.y - sMin.y);
  p[2][1] = (sMax.y + sMin.y) / (sMax.y - sMin.y);
  const double zn = nearD * (1.0 - 1e-9), zf = farD * (1.0 + 1e-9);
  p[2][2] = -(zf + zn) / (zf - zn);
  p[3][2] = -2.0 * zf * zn / (zf - zn);
  p[2][3] = -1.0;
  return p;
}

}  // namespace

LispsmCamera fitLispsm(const CameraFrustum& camera, const glm::dvec3& lightDirection, std::span<const glm::dvec3> pts,
                       DepthRange range, double nOverride,
                       const std::function<double(double, double, double)>& optimalN) {
  requireFinite(lightDirection, "lightDirection");
  if (!(glm::length(lightDirection) > 0.0)) throw std::invalid_argument("lightDirection is the zero vector");
  if (pts.empty()) throw std::invalid_argument("LiSPSM needs at least one world point");
  LispsmCamera out;
  const glm::dvec3 L = glm::normalize(lightDirection);
  const glm::dmat3 rot(camera.view);
  const glm::dvec3 viewDir = -glm::transpose(rot)[2];  // world direction of view -z
  out.gamma = std::acos(std::clamp(glm::dot(viewDir, L), -1.0, 1.0));
  // Frame: y toward the light, z opposite to the projected view direction (the perspective
  // looks down -z, along the projected view direction), x completes a right-handed frame.
  glm::dvec3 up = -L;
  glm::dvec3 proj = viewDir - glm::dot(viewDir, up) * up;
  const double pl = glm::length(proj);
  const bool degenerate = pl < 1e-9;
  if (degenerate) proj = anyPerpendicular(up);
  else proj /= pl;
  const glm::dvec3 zAxis = -proj;
  const glm::dvec3 xAxis = glm::cross(up, zAxis);
  auto toFrame = [&](const glm::dvec3& p) {
    return glm::dvec3(glm::dot(xAxis, p), glm::dot(up, p), glm::dot(zAxis, p));
  };
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const auto& p : pts) {
    const glm::dvec3 q = toFrame(p);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const double depth = std::max(hi.z - lo.z, 1e-12);  // body extent along the projected view
  // n_opt from the body's own view-depth range [z0, z1] (Wimmer et al.'s general form), which is
  // the frustum's [zn, zf] when the receivers fill it.
  double z0 = std::numeric_limits<double>::max(), z1 = 0.0;
  for (const auto& p : pts) {
    const double z = -(camera.view * glm::dvec4(p, 1.0)).z;
    z0 = std::min(z0, z);
    z1 = std::max(z1, z);
  }
  z0 = std::max(z0, camera.zNear);
  z1 = std::max(z1, z0 * (1.0 + 1e-9));
  const double n = nOverride > 0.0 ? nOverride
                   : optimalN      ? optimalN(z0, z1, out.gamma)
                                   : lispsmOptimalN(z0, z1, out.gamma);
  const glm::dmat4 remap = depthRangeRemap(range);
  const glm::dmat4 swz = lispsmSwizzle();
  glm::dmat4 frame(1.0);
  for (int c = 0; c < 3; ++c) {
    frame[c][0] = xAxis[c];
    frame[c][1] = up[c];
    frame[c][2] = zAxis[c];
  }
  const glm::dvec3 pad = glm::max(hi - lo, glm::dvec3(1e-12)) * 1e-7 + 1e-12;
  if (degenerate || !(n > 0.0) || !std::isfinite(n) || n > 1e6 * depth) {
    // Uniform fallback: orthographic box over the body in the frame; it maps frame z to [-1,1]
    // increasing with z, and the map's y comes from it via the swizzle.
    out.worldToClip = remap * swz * frameBox(lo, hi, pad) * frame;
    out.n = std::numeric_limits<double>::infinity();
    out.perspective = false;
    return out;
  }
  // Perspective centre: n in front of the body's near side (largest frame z), looking down -z.
  const double zEye = hi.z + n;
  const double nearD = n, farD = n + depth;
  glm::dvec2 sMin(std::numeric_limits<double>::max()), sMax(-std::numeric_limits<double>::max());
  for (const auto& p : pts) {
    const glm::dvec3 q = toFrame(p);
    const double Z = zEye - q.z;
    const glm::dvec2 s(q.x / Z, q.y / Z);
    sMin = glm::min(sMin, s);
    sMax = glm::max(sMax, s);
  }
  const glm::dvec2 sp = glm::max(sMax - sMin, glm::dvec2(1e-12)) * 1e-7 + 1e-15;
  sMin -= sp;
  sMax += sp;
  glm::dmat4 shift(1.0);
  shift[3][2] = -zEye;
  // After the warp the map's y is its NDC z (along the projected view), depth its NDC y (the light).
  out.worldToClip = remap * swz * warpPerspective(sMin, sMax, nearD, farD) * shift * frame;
  out.n = n;
  out.perspective = true;
  return out;
}

}  // namespace shadowlab::psm

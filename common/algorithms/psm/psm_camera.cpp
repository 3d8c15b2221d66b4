#include "algorithms/psm/psm_camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadowlab::psm {

namespace {

[[noreturn]] void fail(const std::string& what, double value) {
  throw std::invalid_argument(what + " = " + std::to_string(value) + " is invalid");
}

void checkFrustumShape(double fovY, double aspect) {
  if (!std::isfinite(fovY) || fovY <= 0.0 || fovY >= std::numbers::pi) fail("fovY", fovY);
  if (!std::isfinite(aspect) || aspect <= 0.0) fail("aspect", aspect);
}

glm::dmat4 orthoGL(double l, double r, double b, double t, double n, double f) {
  glm::dmat4 m(1.0);
  m[0][0] = 2.0 / (r - l);
  m[1][1] = 2.0 / (t - b);
  m[2][2] = -2.0 / (f - n);
  m[3][0] = -(r + l) / (r - l);
  m[3][1] = -(t + b) / (t - b);
  m[3][2] = -(f + n) / (f - n);
  return m;
}

// Margins that keep rounding from pushing boundary points out of the map.
constexpr double kAngleMargin = 1e-7;
constexpr double kDepthMargin = 1e-9;

void finish(LightCamera& cam, const glm::dmat4& cameraViewProj) {
  cam.postToClip = cam.projection * cam.view;
  cam.worldToClip = cam.postToClip * cameraViewProj;
}

}  // namespace

glm::dmat4 inverseProjection(double fovY, double aspect, double a, DepthRange range) {
  checkFrustumShape(fovY, aspect);
  if (!std::isfinite(a) || a <= 0.0) fail("a", a);
  const double t = 1.0 / std::tan(fovY / 2.0);
  glm::dmat4 m(0.0);
  m[0][0] = t / aspect;
  m[1][1] = t;
  m[3][2] = a;     // z_clip = a * w_in: GL's perspective with n = -a, f = +a
  m[2][3] = -1.0;  // w_clip = -z_view = Z
  return depthRangeRemap(range) * m;
}

glm::dmat4 reversedProjection(double fovY, double aspect, double f, DepthRange range) {
  checkFrustumShape(fovY, aspect);
  if (!std::isfinite(f) || f <= 0.0) fail("f", f);
  const double t = 1.0 / std::tan(fovY / 2.0);
  glm::dmat4 m(0.0);
  m[0][0] = t / aspect;
  m[1][1] = t;
  m[2][2] = 1.0;  // z_clip = z_view + 2 f: depth = -1 + 2 f / Z
  m[3][2] = 2.0 * f;
  m[2][3] = -1.0;
  return depthRangeRemap(range) * m;
}

namespace {

void checkOptions(const PsmOptions& opt) {
  if (!(opt.nearFraction > 0.0 && opt.nearFraction < 1.0)) fail("nearFraction", opt.nearFraction);
  if (!(opt.maxHalfAngle > 0.0 && opt.maxHalfAngle < std::numbers::pi / 2.0)) fail("maxHalfAngle", opt.maxHalfAngle);
}

// Parallel rays in post-projective space (the light is at infinity toward +direction): an
// orthographic box around the points, reaching toward the light over the whole unit cube.
void fitOrthographic(const PostProjectiveLight& light, std::span<const glm::dvec3> pts, const PsmOptions& opt,
                     LightCamera& cam) {
  cam.kind = LightProjection::Orthographic;
  cam.axis = -light.direction;
  glm::dvec3 centre(0.0);
  for (const auto& p : pts) centre += p;
  centre /= static_cast<double>(pts.size());
  cam.eye = centre - cam.axis * 4.0;  // outside the unit cube (radius sqrt 3)
  cam.view = lookAlong(cam.eye, cam.axis);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const auto& p : pts) {
    const glm::dvec3 v(cam.view * glm::dvec4(p, 1.0));
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  // Casters toward the light: include the whole unit cube on that side.
  double cubeFar = 0.0;  // largest view z (closest to the light) over the cube's corners
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 c((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    cubeFar = std::max(cubeFar, (cam.view * glm::dvec4(c, 1.0)).z);
  }
  const glm::dvec3 ext = glm::max(hi - lo, glm::dvec3(1e-12));
  const glm::dvec3 pad = ext * kAngleMargin + 1e-15;
  const double n = -std::max(hi.z, cubeFar) - pad.z;
  const double f = -lo.z + pad.z;
  cam.zNear = n;
  cam.zFar = f;
  cam.projection =
      depthRangeRemap(opt.depthRange) * orthoGL(lo.x - pad.x, hi.x + pad.x, lo.y - pad.y, hi.y + pad.y, n, f);
}

// The projection along the cone's axis, by where the light is: in front (perspective), behind
// (fix 1's inverse projection, or the original's reversed one after its slide).
void setConeProjection(const PostProjectiveLight& light, double zMin, double zMax, const PsmOptions& opt,
                       LightCamera& cam) {
  const double fov = 2.0 * cam.halfAngle;
  if (light.kind == PostLightKind::InFront) {
    cam.kind = LightProjection::Perspective;
    cam.zNear = opt.nearFraction * zMin;
    cam.zFar = zMax * (1.0 + kDepthMargin) + std::numeric_limits<double>::min();
    cam.projection = depthRangeRemap(opt.depthRange) * perspectiveGL(fov, 1.0, cam.zNear, cam.zFar);
  } else if (opt.behind == BehindProjection::Inverse) {
    cam.kind = LightProjection::Inverse;
    const double a = zMin * (1.0 - kDepthMargin);
    cam.zNear = -a;
    cam.zFar = a;
    cam.projection = opt.steps.inverseProjection
                         ? depthRangeRemap(opt.depthRange) * opt.steps.inverseProjection(fov, 1.0, a)
                         : inverseProjection(fov, 1.0, a, opt.depthRange);
  } else {
    cam.kind = LightProjection::ReversedPerspective;
    cam.zNear = std::numeric_limits<double>::infinity();
    cam.zFar = zMin * (1.0 - kDepthMargin);
    cam.projection = reversedProjection(fov, 1.0, cam.zFar, opt.depthRange);
  }
}

// Least and greatest distance along cam.axis over the points (capped: only those inside the
// camera's cone). One loop per case: no per-point root when nothing is capped.
std::pair<double, double> depthAlongAxis(std::span<const glm::dvec3> pts, const LightCamera& cam, bool capped) {
  double zMin = std::numeric_limits<double>::max(), zMax = 0.0;
  auto scan = [&](auto held) {
    for (const auto& p : pts) {
      const double z = glm::dot(p - cam.eye, cam.axis);
      if (!held(p, z)) continue;
      zMin = std::min(zMin, z);
      zMax = std::max(zMax, z);
    }
  };
  if (capped) {
    const double cosHalf = std::cos(cam.halfAngle);
    scan([&](const glm::dvec3& p, double z) { return !(z < glm::length(p - cam.eye) * cosHalf); });
  } else {
    scan([](const glm::dvec3&, double) { return true; });
  }
  return {zMin, zMax};
}

PsmFit fitImpl(const PostProjectiveLight& light, std::span<const glm::dvec3> pts, const glm::dmat4& cameraViewProj,
               const PsmOptions& opt, std::vector<glm::dvec3>& scratch) {
  checkOptions(opt);
  PsmFit fit;
  fit.light = light;
  if (pts.empty()) {
    fit.status = FitStatus::NoReceivers;
    return fit;
  }
  LightCamera& cam = fit.camera;
  if (light.kind == PostLightKind::Direction) {
    fitOrthographic(light, pts, opt, cam);
    finish(cam, cameraViewProj);
    fit.status = FitStatus::Ok;
    return fit;
  }
  // Finite light (in front or behind): smallest cone from the light over the key points.
  ConeFit cf;
  if (opt.steps.cone) {  // the student's cone gets the directions; the depth range is measured below
    scratch.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      scratch[i] = pts[i] - light.position;
      if (!(glm::dot(scratch[i], scratch[i]) > 0.0)) cf.bad = i;
    }
    if (cf.bad >= pts.size()) cf.cone = opt.steps.cone(scratch);
  } else {
    cf = enclosingConeFrom(light.position, pts, scratch);
  }
  if (cf.bad < pts.size()) {  // a receiver exactly at the light (or not finite): no cone can be aimed
    fit.status = FitStatus::ConeTooWide;
    return fit;
  }
  fit.cone = cf.cone;
  if (!fit.cone.valid || !(fit.cone.halfAngle <= opt.maxHalfAngle || opt.capWideCones)) {
    fit.status = FitStatus::ConeTooWide;
    return fit;
  }
  cam.eye = light.position;
  cam.axis = fit.cone.axis;
  cam.halfAngle = std::min(fit.cone.halfAngle, opt.maxHalfAngle) * (1.0 + kAngleMargin) + 1e-12;
  cam.view = lookAlong(cam.eye, cam.axis);
  // Depth range over the points the map holds: all of them (measured with the cone), unless a
  // capped cone (or the student's) left some out.
  const bool capped = fit.cone.halfAngle > opt.maxHalfAngle;
  const auto [zMin, zMax] =
      capped || opt.steps.cone ? depthAlongAxis(pts, cam, capped) : std::pair<double, double>(cf.minAlong, cf.maxAlong);
  if (!(zMin > 0.0) || zMin > zMax) {  // a capped cone holding no point: nothing to aim at
    fit.status = FitStatus::ConeTooWide;
    return fit;
  }
  setConeProjection(light, zMin, zMax, opt, cam);
  finish(cam, cameraViewProj);
  fit.status = FitStatus::Ok;
  return fit;
}

}  // namespace

PsmFit fitLightCamera(const PostProjectiveLight& light, std::span<const glm::dvec3> postPoints,
                      const glm::dmat4& cameraViewProj, const PsmOptions& options, std::vector<glm::dvec3>& scratch) {
  return fitImpl(light, postPoints, cameraViewProj, options, scratch);
}

const PsmFit& PsmFitter::fit(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                             const PsmOptions& options) {
  const PostProjectiveLight pl = toPostProjective(camera.viewProj, light);
  const Frustum frustum = frustumFromViewProj(camera.viewProj, camera.invViewProj);
  receiverKeyPoints(receivers, frustum, world_);
  toPostProjectivePoints(camera.viewProj, world_, post_);
  fit_ = fitImpl(pl, post_, camera.viewProj, options, scratch_);
  return fit_;
}

double virtualCameraShift(const glm::dmat4& view, double zNear, std::span<const glm::dvec3> corners) {
  double shift = 0.0;
  for (const glm::dvec3& c : corners) {
    const double z = (view * glm::dvec4(c, 1.0)).z;  // in front: z <= -zNear
    shift = std::max(shift, z + zNear);
  }
  return shift;
}

double virtualCameraShift(const CameraFrustum& camera, std::span<const Aabb> casters) {
  double shift = 0.0;
  for (const Aabb& b : casters) {
    validateBox(b);
    glm::dvec3 corners[8];
    for (int i = 0; i < 8; ++i)
      corners[i] = glm::dvec3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    shift = std::max(shift, virtualCameraShift(camera.view, camera.zNear, corners));
  }
  return shift;
}

OriginalPsm fitOriginalPsm(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                           std::span<const Aabb> casters, const PsmOptions& options,
                           std::vector<glm::dvec3>& worldScratch, std::vector<glm::dvec3>& postScratch,
                           std::vector<glm::dvec3>& dirScratch) {
  OriginalPsm out;
  const PostProjectiveLight real = toPostProjective(camera.viewProj, light);
  // Casters behind the camera only matter when the light is behind it (they lie on the rays to
  // visible receivers only then), so only then does the original slide the camera back.
  out.shift = real.kind == PostLightKind::Behind ? virtualCameraShift(camera, casters) : 0.0;
  glm::dmat4 slide(1.0);
  slide[3][2] = -out.shift;  // view z' = z - shift: the eye moved back along its forward axis
  out.virtualCamera =
      makeCamera(slide * camera.view, camera.fovY, camera.aspect, camera.zNear + out.shift, camera.zFar + out.shift);
  const Frustum frustum = frustumFromViewProj(camera.viewProj, camera.invViewProj);
  receiverKeyPoints(receivers, frustum, worldScratch);
  toPostProjectivePoints(out.virtualCamera.viewProj, worldScratch, postScratch);
  const PostProjectiveLight virt = toPostProjective(out.virtualCamera.viewProj, light);
  PsmOptions reversed = options;
  reversed.behind = BehindProjection::Reversed;
  out.fit = fitImpl(virt, postScratch, out.virtualCamera.viewProj, reversed, dirScratch);
  return out;
}

}  // namespace shadowlab::psm

#include "algorithms/psm/psm_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/psm/bias.hpp"
#include "algorithms/psm/lispsm.hpp"

namespace shadowlab::psm {

namespace {
constexpr double kMaxDepthRatio = 500.0;  // the PSM camera's largest far / near (fix 2)
}  // namespace

int faceMapSize(int side, int count) {
  if (count <= 1) return std::max(side, 1);
  return std::max(1, int(std::floor(double(side) / std::sqrt(double(count)))));
}

glm::dmat4 mapTexelOffset(const glm::dmat4& worldToClip, int size) {
  return texelOffsetMatrix(worldToClip, glm::dvec2(double(size)));
}

const PsmPlan& PsmPlanner::plan(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                                std::span<const Aabb> objects, std::span<const Aabb> casters, const PsmSwitches& s) {
  auto toPost = [&](const glm::dmat4& viewProj) {
    return s.toPostProjective ? s.toPostProjective(viewProj, light)
                              : toPostProjective(viewProj, light, s.directionTolerance);
  };
  plan_ = {};
  plan_.camera = camera;
  plan_.realLight = toPost(camera.viewProj);
  plan_.light = plan_.realLight;
  // ==== the original's virtual camera: slid back until every potential caster is in front ====
  if (plan_.realLight.kind == PostLightKind::Behind && !s.inverseProjection) {
    plan_.shift = s.virtualShift ? s.virtualShift(camera, casters) : virtualCameraShift(camera, casters);
    if (!(plan_.shift >= 0.0) || !std::isfinite(plan_.shift)) plan_.shift = 0.0;  // a broken student shift
    if (plan_.shift > 0.0) {
      glm::dmat4 slide(1.0);
      slide[3][2] = -plan_.shift;  // view z' = z - shift: the eye moved back along its forward axis
      plan_.camera = makeCamera(slide * camera.view, camera.fovY, camera.aspect, camera.zNear + plan_.shift,
                                camera.zFar + plan_.shift);
      plan_.light = toPost(plan_.camera.viewProj);
    }
  }
  // ==== the key points: receivers clipped by the real frustum (fix 2), or every object ====
  if (s.receiverClipping)
    receiverKeyPoints(receivers, frustumFromViewProj(camera.viewProj, camera.invViewProj), world_);
  else receiverKeyPoints(objects, frustumFromViewProj(plan_.camera.viewProj, plan_.camera.invViewProj), world_);
  if (world_.empty()) {
    post_.clear();
    plan_.status = PlanStatus::NothingInView;
    return plan_;
  }
  // Fix 2's key points also bound the depth the map must serve (§4.1: "they give the near plane"):
  // the camera's near and far planes move onto them, the cube holds the receivers only, and a
  // directional light's plane at infinity moves away from the cube (narrower cones).
  if (s.receiverClipping && plan_.shift == 0.0) {
    double zMin = std::numeric_limits<double>::max(), zMax = 0.0;
    for (const glm::dvec3& p : world_) {
      const double z = -(camera.view * glm::dvec4(p, 1.0)).z;
      zMin = std::min(zMin, z);
      zMax = std::max(zMax, z);
    }
    // Never closer than far / kMaxDepthRatio: at Zf/Zn = 1e4 and more a directional light lands
    // 1e-4 behind the far face and the map's matrices lose texels in float (measured: 6 texels of a
    // 1024 map at 3e4, a fifth of one at 500). Receivers nearer than that (the eye inside a rough
    // volume) lie in front of the near face, outside the cube: a single map still holds them.
    const double n = std::max({camera.zNear, zMin * (1.0 - 1e-6), zMax / kMaxDepthRatio});
    const double f = std::max(zMax * (1.0 + 1e-6), n * (1.0 + 1e-3));
    plan_.camera =
        makeCamera(camera.view, camera.fovY, camera.aspect, n, std::min(f, std::max(camera.zFar, n * 1.001)));
    plan_.light = toPost(plan_.camera.viewProj);
  }
  toPostProjectivePoints(plan_.camera.viewProj, world_, post_);
  plan_.postZMin = plan_.nearestDepth = std::numeric_limits<double>::max();
  plan_.postZMax = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < post_.size(); ++i) {
    plan_.postZMin = std::min(plan_.postZMin, post_[i].z);
    plan_.postZMax = std::max(plan_.postZMax, post_[i].z);
    plan_.nearestDepth = std::min(plan_.nearestDepth, -(plan_.camera.view * glm::dvec4(world_[i], 1.0)).z);
  }
  // ==== the light camera: one map, or the hidden faces of the unit cube (fix 3) ====
  if (s.faces == FaceMode::Always) fitFaces(s);
  else fitSingle(s);
  if (light.w == 0.0 && plan_.status == PlanStatus::Ok) chooseFallback(s, camera, light, receivers);
  return plan_;
}

// The warp's maps against the uniform map fitted to the same key points (LiSPSM's n -> infinity: an
// orthographic box along the light), by their predicted mean aliasing (texel_density.hpp); the
// prediction is made (and shown) with the switch off too.
void PsmPlanner::chooseFallback(const PsmSwitches& s, const CameraFrustum& camera, const glm::dvec4& light,
                                std::span<const Aabb> receivers) {
  std::array<glm::dmat4, 6> warped;
  for (int k = 0; k < plan_.mapCount; ++k) warped[std::size_t(k)] = plan_.maps[std::size_t(k)].camera.worldToClip;
  const glm::dmat4 uniform =
      fitLispsm(plan_.camera, -glm::dvec3(light), world_, s.options.depthRange, std::numeric_limits<double>::infinity())
          .worldToClip;
  if (seen_.empty()) screenSurfaceSamples(camera, receivers, 16, 9, samples_);
  else samples_.assign(seen_.begin(), seen_.end());
  plan_.warped = predictAliasing(camera, s.screenHeight, samples_, {warped.data(), std::size_t(plan_.mapCount)},
                                 faceMapSize(s.mapSide, plan_.mapCount), light);
  plan_.uniform = predictAliasing(camera, s.screenHeight, samples_, {&uniform, 1}, s.mapSide, light);
  if (!s.uniformFallback || plan_.uniform.points == 0) return;
  if (!(plan_.warped.meanAliasing > s.fallbackRatio * plan_.uniform.meanAliasing)) return;
  LightCamera c;
  c.kind = LightProjection::Orthographic;
  c.worldToClip = uniform;
  c.postToClip = uniform * plan_.camera.invViewProj;
  plan_.maps = {};
  plan_.maps[0] = {c, -1};
  plan_.mapCount = 1;
  plan_.faces = false;
  plan_.faceMask = 0;
  plan_.cone = {};
  plan_.pointsOutside = 0;
  plan_.fallback = true;
}

void PsmPlanner::fitSingle(const PsmSwitches& s) {
  PsmOptions o = s.options;
  if (s.faces == FaceMode::Never) {  // the original: one map, however wide
    o.maxHalfAngle = s.singleMapMaxHalfAngle;
    o.capWideCones = true;
  }
  o.behind = s.inverseProjection ? BehindProjection::Inverse : BehindProjection::Reversed;
  const PsmFit fit = fitLightCamera(plan_.light, post_, plan_.camera.viewProj, o, scratch_);
  plan_.cone = fit.cone;
  if (fit.status == FitStatus::Ok) {
    plan_.maps[0] = {fit.camera, -1};
    plan_.mapCount = 1;
    plan_.status = PlanStatus::Ok;
    if (fit.camera.kind == LightProjection::Orthographic || !(fit.cone.halfAngle > o.maxHalfAngle)) return;
    const double cosHalf = std::cos(fit.camera.halfAngle);
    for (const glm::dvec3& p : post_) {
      const glm::dvec3 d = p - fit.camera.eye;
      plan_.pointsOutside += glm::dot(d, fit.camera.axis) < glm::length(d) * cosHalf;
    }
    return;
  }
  if (s.faces == FaceMode::Auto) fitFaces(s);
  else plan_.status = PlanStatus::NoLightCamera;
}

void PsmPlanner::fitFaces(const PsmSwitches& s) {
  const CubeFaceSet set = cubeFaceCameras(plan_.light, plan_.camera.viewProj, post_, s.options);
  plan_.faces = true;
  plan_.faceMask = set.hiddenMask;
  plan_.mapCount = 0;
  for (int f = 0; f < 6; ++f)
    if (set.faces[std::size_t(f)].used)
      plan_.maps[std::size_t(plan_.mapCount++)] = {set.faces[std::size_t(f)].camera, f};
  plan_.status = plan_.mapCount > 0 ? PlanStatus::Ok : PlanStatus::NoLightCamera;
}

}  // namespace shadowlab::psm

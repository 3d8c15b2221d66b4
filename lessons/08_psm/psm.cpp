#include "psm.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "algorithms/psm/post_shapes.hpp"
#include "algorithms/psm/receivers.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

const glm::vec4 kVolumeColour{0.45f, 0.75f, 0.45f, 1.0f};
const glm::vec4 kKeyPointColour{0.4f, 1.0f, 0.5f, 1.0f};
const glm::vec4 kVirtualColour{1.0f, 0.5f, 0.2f, 1.0f};
const glm::vec4 kMapColour{0.3f, 0.85f, 1.0f, 1.0f};

std::string degrees(double radians) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f deg", radians * 180.0 / 3.14159265358979);
  return b;
}

// Below this share of post-projective depth the receivers are squeezed against its far side. The
// city's default view, nearest receiver 4.15 away (misclassified against the ground truth):
// camera.near 1 leaves them 24 % (1.3 %), 0.5 12 % (2.7 %), 0.1 2.4 % (12.9 %), 0.05 1.2 % (21 %),
// 0.01 0.24 % (52.5 %: every shadow gone).
constexpr double kThinPostDepth = 0.05;

const char* kindName(psm::PostLightKind k) {
  return k == psm::PostLightKind::InFront ? "in front" : k == psm::PostLightKind::Behind ? "behind" : "direction";
}

// True when every corner of the volume worldToClip maps onto the clip cube is a finite world
// point on the same side of infinity: a frustum the god view can draw as a box.
bool finiteInWorld(const glm::dmat4& worldToClip) {
  const glm::dmat4 inv = glm::inverse(worldToClip);
  double sign = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 h = inv * glm::dvec4((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1);
    if (!(std::abs(h.w) > 1e-12 * glm::length(glm::dvec3(h))) || (sign != 0.0 && h.w * sign < 0.0)) return false;
    sign = h.w;
  }
  return true;
}

}  // namespace

PsmParams PsmParams::original() {
  PsmParams p;
  p.inverseProjection = false;
  p.receiverClipping = false;
  p.faces = psm::FaceMode::Never;
  p.uniformFallback = false;
  p.maps.bias = ProjectiveBias::Constant;
  p.maps.normalOffset = 0.0f;    // the original knew no normal offset either
  p.maps.receiverPlane = false;  // nor the receiver plane
  return p;
}

psm::CameraFrustum viewerFrustum(const ShadowContext& c) {
  return psm::makeCamera(glm::dmat4(c.viewer.view()), c.viewer.fovY, c.viewerAspect(), c.viewer.nearZ, c.viewer.farZ);
}

void PerspectiveShadowMaps::declare(ParamRegistry& r, const std::string& n) {
  maps_.declare(r, n);
  r.add(n + "fix.inverse", &p_.inverseProjection,
        "fix 1: a light behind the camera gets the inverse projection (off: the virtual camera slides back)");
  r.add(n + "fix.clip", &p_.receiverClipping,
        "fix 2: fit to the receivers' rough volumes inside the view, along the smallest cone (off: every object)");
  r.addChoice(n + "fix.faces", &p_.faces, {"never", "auto", "always"},
              "fix 3: a map on each unit-cube face hidden from the light: never, when the cone is too wide, always");
  r.add(n + "fix.fallback", &p_.uniformFallback,
        "a directional light whose warp is predicted to alias more than the uniform map gets the uniform map");
  r.add(n + "fallback.ratio", &p_.fallbackRatio, 0.1f, 10.0f,
        "fix.fallback: the warp's predicted mean aliasing over the uniform map's past which it falls back");
  r.add(n + "receivers.tiles", &p_.receiverTiles, 1, 64,
        "rough receiver volumes: large objects cut into cells of scene size / tiles (1: object boxes)");
  r.add(n + "cone.max", &p_.maxConeDegrees, 10, 89,
        "fix.faces=auto: a cone half-angle (degrees) past which faces take over");
  r.add(n + "near_fraction", &p_.nearFraction, 0.01f, 0.99f,
        "a light in front: its near plane at this share of the nearest key point");
  r.add(n + "cull_casters", &p_.cullCasters, "draw only the casters that can shade the view frustum");
}

psm::PsmSwitches PerspectiveShadowMaps::switches() const {
  psm::PsmSwitches s;
  s.toPostProjective = student.toPostProjective;
  s.virtualShift = student.virtualShift;
  s.options.steps = student.fixes;
  s.inverseProjection = p_.inverseProjection;
  s.receiverClipping = p_.receiverClipping;
  s.faces = p_.faces;
  s.uniformFallback = p_.uniformFallback;
  s.fallbackRatio = double(p_.fallbackRatio);
  s.mapSide = maps_.totalSide();
  s.options.depthRange = psm::DepthRange::MinusOneToOne;
  s.options.maxHalfAngle = double(p_.maxConeDegrees) * 3.14159265358979323846 / 180.0;
  s.options.nearFraction = p_.nearFraction;
  return s;
}

// ==== 1. the plan: the light in post-projective space, the key points, the light camera(s) =====
void PerspectiveShadowMaps::planLight(const ShadowContext& c, int i, const psm::CameraFrustum& camera) {
  const Light& light = c.lights[std::size_t(i)];
  PerLight& l = lights_[std::size_t(i)];
  l.planned = false;
  if (!light.enabled) return;
  const glm::dvec4 h = psm::homogeneousLight(light);
  const psm::Frustum frustum = psm::frustumFromViewProj(camera.viewProj, camera.invViewProj);
  // The slide covers the potential casters, whether or not the depth pass culls the others.
  const int culled = selectCasters(c.scene, frustum, h, true, l.keep);
  l.casterBoxes.clear();
  for (std::size_t j = 0; j < l.keep.size(); ++j)
    if (l.keep[j]) l.casterBoxes.push_back(c.scene.boxes()[j]);
  if (p_.cullCasters) stats_.culledCasters += culled;
  else l.keep.assign(c.scene.casts().begin(), c.scene.casts().end());
  psm::PsmSwitches s = switches();
  s.screenHeight = std::max(1, c.frame.height);
  l.planner.plan(camera, h, receivers_, c.scene.boxes(), l.casterBoxes, s);
  l.planned = true;
  addCounters(i);
}

// ==== 2. the depth passes: one per map, casters that can shade the view only ===================
void PerspectiveShadowMaps::renderLight(const ShadowContext& c, int i) {
  const psm::PsmPlan* p = plan(i);
  if (!p || p->status != psm::PlanStatus::Ok) return maps_.disable(i);
  const psm::PsmPlan& plan = *p;
  ProjectiveMapView views[kPsmMaps];
  FaceLookup faces;
  faces.faces = plan.faces;
  faces.cameraViewProj = plan.camera.viewProj;
  faces.postLight = plan.light.kind == psm::PostLightKind::Direction ? glm::dvec4(plan.light.direction, 0.0)
                                                                     : glm::dvec4(plan.light.position, 1.0);
  faces.layerOfFace.fill(-1);
  for (int k = 0; k < plan.mapCount; ++k) {
    views[k].worldToClip = plan.maps[std::size_t(k)].camera.worldToClip;
    if (plan.maps[std::size_t(k)].face >= 0) faces.layerOfFace[std::size_t(plan.maps[std::size_t(k)].face)] = k;
  }
  const int side = psm::faceMapSize(maps_.totalSide(), plan.mapCount);
  maps_.render(c, i, {views, std::size_t(plan.mapCount)}, side, lights_[std::size_t(i)].keep,
               psm::homogeneousLight(c.lights[std::size_t(i)]), faces, stats_);
}

void PerspectiveShadowMaps::render(const ShadowContext& c) {
  planLights(c);
  renderDepth(c);
}

void PerspectiveShadowMaps::planLights(const ShadowContext& c) {
  maps_.student = {student.worldBias, student.glslLookup, student.glslFaces};  // the maps' share of the steps
  stats_ = {};
  receivers_ = receiverCache_.get(c.scene, p_.receiverTiles);
  lights_.resize(kPsmLights);
  const psm::CameraFrustum camera = viewerFrustum(c);
  // The fall-back (a directional light's) predicts m where the camera's pixels land: 16 x 9 rays
  // into the scene, cast only for a directional light and again only when the scene or the camera moved.
  bool directional = false;
  for (int i = 0; i < kPsmLights && i < int(c.lights.size()); ++i)
    directional =
        directional || (c.lights[std::size_t(i)].enabled && c.lights[std::size_t(i)].kind == LightKind::Directional);
  PassKey seen;
  seen << c.scene.revision() << camera.viewProj;
  if (directional && !(seen == seenKey_)) {
    psm::screenSceneSamples(camera, c.scene.scene(), 16, 9, seen_);
    seenKey_ = std::move(seen);
  }
  for (int i = 0; i < kPsmLights; ++i) {
    lights_[std::size_t(i)].planner.setSeen(seen_);
    if (i < int(c.lights.size())) planLight(c, i, camera);
    else lights_[std::size_t(i)].planned = false;
  }
  for (std::size_t i = kPsmLights; i < c.lights.size(); ++i)
    if (c.lights[i].enabled)
      stats_.extra.push_back(
          {"light" + std::to_string(i), "no PSM map (" + std::to_string(kPsmLights) + " lights at most)"});
  stats_.extra.push_back({"receiver volumes", std::to_string(receivers_.size())});
}

void PerspectiveShadowMaps::renderDepth(const ShadowContext& c) {
  for (int i = 0; i < kPsmLights; ++i) renderLight(c, i);
}

void PerspectiveShadowMaps::addCounters(int i) {
  const psm::PsmPlan& plan = lights_[std::size_t(i)].planner.result();
  const std::string n = "light" + std::to_string(i) + " ";
  std::string where = kindName(plan.realLight.kind);
  if (plan.shift > 0.0) where += ", camera slid back " + std::to_string(plan.shift).substr(0, 6);
  stats_.extra.push_back({n + "light", where});
  if (plan.status == psm::PlanStatus::NothingInView) {
    stats_.extra.push_back({n + "maps", "none: no receiver in view"});
    return;
  }
  if (plan.status == psm::PlanStatus::NoLightCamera) {
    stats_.extra.push_back({n + "maps", "none: no cone holds the receivers (turn fix.faces on)"});
    return;
  }
  const int side = psm::faceMapSize(maps_.totalSide(), plan.mapCount);
  const std::string size = std::to_string(side) + "^2";
  stats_.extra.push_back({n + "maps", plan.fallback ? "1 uniform map " + size + " (fallback)"
                                      : plan.faces  ? std::to_string(plan.mapCount) + " cube faces of " + size
                                                    : "1 map " + size});
  if (plan.uniform.points > 0) {
    char b[96];
    const double ratio = plan.warped.meanAliasing / plan.uniform.meanAliasing;
    if (std::isfinite(ratio))
      std::snprintf(b, sizeof b, "%.3g, %.2fx the uniform map's%s", plan.warped.meanAliasing, ratio,
                    plan.fallback ? ": the uniform map" : "");
    else std::snprintf(b, sizeof b, "unbounded: receivers with no texel%s", plan.fallback ? ": the uniform map" : "");
    stats_.extra.push_back({n + "warp's predicted m", b});
  }
  if (!plan.faces && plan.cone.valid) stats_.extra.push_back({n + "cone", degrees(plan.cone.halfAngle)});
  // The original's weakness, said when it bites: a near plane far nearer than the receivers squeezes
  // them against z = 1 of post-projective space, and the map spends its texels and depth on the
  // empty rest (lesson 08's near_plane preset; fix 2's near plane on the receivers cures it).
  const double share = (plan.postZMax - plan.postZMin) / 2.0;
  if (share < kThinPostDepth) {
    char b[160];
    std::snprintf(b, sizeof b,
                  "the view's receivers fill %.2g %% of it (near plane %.3g, nearest receiver %.3g): raise "
                  "camera.near, or fix.clip",
                  100.0 * share, plan.camera.zNear, plan.nearestDepth);
    stats_.extra.push_back({n + "post-projective depth", b});
  }
  if (plan.pointsOutside > 0)
    stats_.extra.push_back({n + "outside the map", std::to_string(plan.pointsOutside) + " key points (unshadowed)"});
}

std::vector<std::string> PerspectiveShadowMaps::shaderDefines() const { return maps_.shaderDefines(); }

const psm::PsmPlan* PerspectiveShadowMaps::plan(int light) const {
  if (light < 0 || light >= int(lights_.size()) || !lights_[std::size_t(light)].planned) return nullptr;
  return &lights_[std::size_t(light)].planner.result();
}

std::span<const glm::dvec3> PerspectiveShadowMaps::worldKeyPoints(int light) const {
  if (!plan(light)) return {};
  return lights_[std::size_t(light)].planner.worldKeyPoints();
}

glm::dmat4 PerspectiveShadowMaps::postProjectiveCamera(const ShadowContext& c, int light) const {
  const psm::PsmPlan* p = plan(light);
  return p ? p->camera.viewProj : PostProjectiveSubject::postProjectiveCamera(c, light);
}

void PerspectiveShadowMaps::describePostProjective(const ShadowContext& c, int light,
                                                   psm::PostProjectiveShapes& out) const {
  if (const psm::PsmPlan* p = plan(light))
    psm::describePlan(*p, viewerFrustum(c), lights_[std::size_t(light)].planner.postKeyPoints(), out);
}

void PerspectiveShadowMaps::pushShapes(const ShadowContext& c) const {
  for (std::size_t k = 0; k < receivers_.size() && k < 4096; ++k) c.debug.box(receivers_[k], kVolumeColour);
  if (!receivers_.empty()) c.debug.name(kVolumeColour, "receiver volumes");
  for (int i = 0; i < int(lights_.size()); ++i) {
    const psm::PsmPlan* p = plan(i);
    if (!p) continue;
    const auto points = worldKeyPoints(i);
    const std::size_t step = points.size() > 2048 ? points.size() / 2048 + 1 : 1;
    for (std::size_t k = 0; k < points.size(); k += step) c.debug.cross(glm::vec3(points[k]), 0.15f, kKeyPointColour);
    if (!points.empty()) c.debug.name(kKeyPointColour, "key points");
    if (p->shift > 0.0) {
      c.debug.frustum(glm::mat4(p->camera.viewProj), kVirtualColour);
      c.debug.name(kVirtualColour, "the virtual camera, slid back");
    }
    for (const psm::PsmMap& m : p->used())
      if (finiteInWorld(m.camera.worldToClip)) {
        c.debug.frustum(glm::mat4(m.camera.worldToClip), kMapColour);
        c.debug.name(kMapColour, "the light camera of a map");
      }
  }
}

}  // namespace shadowlab::tech

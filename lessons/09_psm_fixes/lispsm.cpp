#include "lispsm.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "algorithms/psm/post_shapes.hpp"
#include "08_psm/psm.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {
const glm::vec4 kFrustumColour{0.3f, 0.85f, 1.0f, 1.0f};
}  // namespace

void LightSpacePsm::declare(ParamRegistry& r, const std::string& n) {
  maps_.declare(r, n);
  r.add(n + "n", &p_.n, 0, 1000, "the warp's n (world units): 0 is n_opt, large is the uniform map, small PSM-like");
  r.add(n + "receivers.tiles", &p_.receiverTiles, 1, 64,
        "rough receiver volumes: large objects cut into cells of scene size / tiles (1: object boxes)");
  r.add(n + "cull_casters", &p_.cullCasters, "draw only the casters that can shade the view frustum");
}

// ==== 1. the light camera: n_opt and the warp in light space (algorithms/psm/lispsm) ============
bool LightSpacePsm::fitLight(const ShadowContext& c, int i, const psm::CameraFrustum& camera) {
  const Light& light = c.lights[std::size_t(i)];
  PerLight& l = lights_[std::size_t(i)];
  const glm::dvec4 h = psm::homogeneousLight(light);
  const psm::Frustum frustum = psm::frustumFromViewProj(camera.viewProj, camera.invViewProj);
  stats_.culledCasters += selectCasters(c.scene, frustum, h, p_.cullCasters, l.keep);
  psm::receiverKeyPoints(receivers_.get(c.scene, p_.receiverTiles), frustum, points_);
  const std::string n = "light" + std::to_string(i) + " ";
  if (points_.empty()) {
    stats_.extra.push_back({n + "maps", "none: no receiver in view"});
    return false;
  }
  if (light.kind == LightKind::Directional) {
    const psm::LispsmCamera fit = psm::fitLispsm(camera, glm::dvec3(light.direction), points_,
                                                 psm::DepthRange::MinusOneToOne, p_.n, student.optimalN);
    l.worldToClip = fit.worldToClip;
    char b[96];
    if (fit.perspective)
      std::snprintf(b, sizeof b, "n %.3g, gamma %.1f deg", fit.n, fit.gamma * 180.0 / 3.14159265358979);
    else
      std::snprintf(b, sizeof b, "no warp (the uniform fallback), gamma %.1f deg",
                    fit.gamma * 180.0 / 3.14159265358979);
    stats_.extra.push_back({n + "warp", b});
    return true;
  }
  // A point or spot light: the smallest cone from it over the receivers, a plain perspective map.
  psm::PostProjectiveLight world;
  world.kind = psm::PostLightKind::InFront;
  world.position = glm::dvec3(light.position);
  const psm::PsmFit fit = psm::fitLightCamera(world, points_, glm::dmat4(1.0), {}, scratch_);
  if (fit.status != psm::FitStatus::Ok) {
    stats_.extra.push_back({n + "maps", "none: the light is among the receivers"});
    return false;
  }
  l.worldToClip = fit.camera.worldToClip;
  stats_.extra.push_back({n + "warp", "none (point light: a cone-fitted perspective map)"});
  return true;
}

// ==== 2. the depth pass: one map per light ======================================================
void LightSpacePsm::pushShapes(const ShadowContext& c) const {
  for (const PerLight& l : lights_)
    if (l.fitted) {
      c.debug.frustum(glm::mat4(l.worldToClip), kFrustumColour);
      c.debug.name(kFrustumColour, "LiSPSM's light frustum");
    }
}

void LightSpacePsm::render(const ShadowContext& c) {
  stats_ = {};
  lights_.resize(kPsmLights);
  const psm::CameraFrustum camera = viewerFrustum(c);
  for (int i = 0; i < kPsmLights; ++i) {
    PerLight& l = lights_[std::size_t(i)];
    l.fitted = i < int(c.lights.size()) && c.lights[std::size_t(i)].enabled && fitLight(c, i, camera);
    if (!l.fitted) {
      maps_.disable(i);
      continue;
    }
    const ProjectiveMapView view{l.worldToClip};
    maps_.render(c, i, {&view, 1}, maps_.totalSide(), l.keep, psm::homogeneousLight(c.lights[std::size_t(i)]), {},
                 stats_);
  }
}

void LightSpacePsm::describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const {
  if (light < 0 || light >= int(lights_.size()) || !lights_[std::size_t(light)].fitted) return;
  out.worldFrustum(postProjectiveCamera(c, light), lights_[std::size_t(light)].worldToClip, kFrustumColour);
}

}  // namespace shadowlab::tech

#include "algorithms/light_cameras.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab::shadow {
namespace {

void requireConsistent(const CasterBoxes& scene) {
  if (scene.casts.size() != scene.boxes.size())
    throw std::invalid_argument("light camera: " + std::to_string(scene.boxes.size()) + " boxes but " +
                                std::to_string(scene.casts.size()) + " caster flags");
}

}  // namespace

void cullAgainst(LightCamera& camera, const CasterBoxes& scene, const ConvexVolume& lightVolume, bool cull,
                 std::span<const char> among) {
  camera.casters.assign(scene.boxes.size(), 0);
  camera.culled = 0;
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    if (!scene.casts[i]) continue;
    const bool candidate = among.empty() || among[i];
    camera.casters[i] = candidate && (!cull || volumesMayIntersect(volumeFromBox(scene.boxes[i]), lightVolume));
    if (!camera.casters[i]) ++camera.culled;
  }
}

ConvexVolume orthoVolumeToward(const LightCamera& ortho, const Aabb& bounds) {
  // glm::ortho's depth row: P[2][2] = -2 / (f - n), P[3][2] = -(f + n) / (f - n), so
  // f = (P[3][2] - 1) / P[2][2] and n = (P[3][2] + 1) / P[2][2].
  glm::mat4 p = ortho.projection;
  const float farZ = (p[3][2] - 1.0f) / p[2][2];
  float nearZ = (p[3][2] + 1.0f) / p[2][2];
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 c((k & 1) ? bounds.max.x : bounds.min.x, (k & 2) ? bounds.max.y : bounds.min.y,
                      (k & 4) ? bounds.max.z : bounds.min.z);
    nearZ = std::min(nearZ, -(ortho.view * glm::vec4(c, 1.0f)).z - 1.0f);  // the light looks down -z
  }
  p[2][2] = -2.0f / (farZ - nearZ);
  p[3][2] = -(farZ + nearZ) / (farZ - nearZ);
  return volumeFromViewProj(p * ortho.view);
}

LightCamera fitDirectional(const glm::vec3& direction, const CasterBoxes& scene, const ConvexVolume& view,
                           const DirectionalFitOptions& o) {
  return fitDirectionalTo(direction, scene, view, {}, o);
}

LightCamera fitDirectionalTo(const glm::vec3& direction, const CasterBoxes& scene, const ConvexVolume& view,
                             std::span<const glm::vec3> given, const DirectionalFitOptions& o) {
  requireConsistent(scene);
  const glm::vec3 d = glm::normalize(direction);
  const CasterTest test = o.casterTest ? o.casterTest : CasterTest(casterMayShadow);
  LightCamera camera;
  camera.casters.assign(scene.boxes.size(), 0);
  std::vector<Aabb> kept;
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    if (!scene.casts[i]) continue;
    const bool keep = !o.cullCasters || test(scene.boxes[i], view, d);
    camera.casters[i] = keep;
    if (keep) kept.push_back(scene.boxes[i]);
    else ++camera.culled;
  }
  // Receivers: where the scene's bounds and the view frustum meet (the whole scene when they do
  // not, or when fitting to the scene); casters only push the near plane toward the light.
  std::vector<glm::vec3> receivers(given.begin(), given.end());
  const ConvexVolume sceneVolume = volumeFromBox(scene.bounds);
  if (o.fitToView && receivers.empty()) receivers = intersectionPoints(sceneVolume, view);
  if (receivers.empty()) receivers.assign(sceneVolume.corners.begin(), sceneVolume.corners.end());
  const std::span<const Aabb> casters = o.fitToView ? std::span<const Aabb>(kept) : std::span<const Aabb>();
  const bool snap = o.snap && o.fitToView;
  const OrthoFit fit = o.fitter ? o.fitter(d, receivers, casters, o.mapSize, snap)
                                : fitOrthographic(d, receivers, casters, o.mapSize, snap, o.snapper);
  camera.view = fit.view;
  camera.projection = fit.projection;
  camera.texelWorld = fit.texelWorld;
  return camera;
}

float spotFieldOfView(const Light& spot) { return std::min(2.0f * spot.spotOuter + 0.05f, 3.0f); }

LightCamera spotCamera(const Light& spot, float nearZ, float farZ, const CasterBoxes& scene, bool cullCasters) {
  requireConsistent(scene);
  LightCamera camera;
  camera.view = lightViewAlong(spot.position, spot.direction);
  camera.projection = glm::perspective(spotFieldOfView(spot), 1.0f, nearZ, std::max(farZ, nearZ + 0.1f));
  cullAgainst(camera, scene, volumeFromViewProj(camera.viewProj()), cullCasters);
  return camera;
}

Map2DCamera fitMap2D(const Light& light, const CasterBoxes& scene, const ConvexVolume& view,
                     const DirectionalFitOptions& o, float spotNear, float spotFar) {
  if (light.kind == LightKind::Point)
    throw std::invalid_argument("fitMap2D: a point light has a cube map, not a 2D map");
  Map2DCamera m;
  m.perspective = light.kind == LightKind::Spot;
  if (!m.perspective) {
    m.camera = fitDirectional(light.direction, scene, view, o);
    m.texel = m.camera.texelWorld;
    m.textureMatrix = textureMatrix(m.camera.projection, m.camera.view);
  } else {
    m.camera = spotCamera(light, spotNear, spotFar, scene, o.cullCasters);
    m.texel = 2.0f * std::tan(0.5f * spotFieldOfView(light)) / float(o.mapSize);
    m.textureMatrix = textureMatrix(glm::mat4(1.0f), m.camera.viewProj());
  }
  return m;
}

std::array<LightCamera, 6> cubeCameras(const glm::vec3& position, float nearZ, float farZ, const CasterBoxes& scene,
                                       const ConvexVolume& view, bool cullCasters, bool skipFaces) {
  requireConsistent(scene);
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, nearZ, std::max(farZ, nearZ + 0.1f));
  std::array<LightCamera, 6> faces;
  for (int face = 0; face < 6; ++face) {
    LightCamera& c = faces[std::size_t(face)];
    c.view = cubeFaceView(position, face);
    c.projection = projection;
    const ConvexVolume faceVolume = volumeFromViewProj(c.viewProj());
    c.skipped = skipFaces && !volumesMayIntersect(faceVolume, view);
    if (c.skipped) c.casters.assign(scene.boxes.size(), 0);
    else cullAgainst(c, scene, faceVolume, cullCasters);
  }
  return faces;
}

}  // namespace shadowlab::shadow

#include "soft_maps.hpp"

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/soft_shadows.hpp"
#include "technique/map_pass.hpp"
#include "technique/map_settings.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {
const glm::vec4 kFrustumColour{1.0f, 0.9f, 0.3f, 1.0f};
}  // namespace

void setTaps(const gl::Program& p, const std::string& name, const std::vector<glm::vec2>& taps) {
  for (std::size_t k = 0; k < taps.size(); ++k) p.set((name + "[" + std::to_string(k) + "]").c_str(), taps[k]);
}

void SoftMaps::declare(ParamRegistry& r, const std::string& n, bool reuseSwitch) {
  declareMapSize(r, n + "map_size", &p_.mapSize, "texels per side of each light sample's map");
  r.add(n + "bias.constant", &p_.bias, 0, 8, "depth bias in texels of world size at the receiver");
  r.add(n + "bias.slope", &p_.slopeBias, 0, 8, "depth bias in texels per unit of tan(theta)");
  r.add(n + "bias.normal_offset", &p_.normalOffset, 0, 4, "look up from this many texels along the normal");
  r.add(n + "bias.offset_factor", &p_.offsetFactor, 0, 8,
        "glPolygonOffset factor in the depth pass (times the depth slope)");
  r.add(n + "bias.offset_units", &p_.offsetUnits, 0, 16, "glPolygonOffset units in the depth pass");
  r.add(n + "bias.card_slope", &p_.cardSlopeBias, 0, 8, "bias.slope on two-sided materials (leaf cards)");
  r.add(n + "bias.card_normal_offset", &p_.cardNormalOffset, 0, 4, "bias.normal_offset on two-sided materials");
  if (reuseSwitch)
    r.add(n + "reuse_maps", &p_.reuseMaps, "keep the maps while nothing they depend on changes (a still light)");
}

int SoftMaps::mapSize() const { return p_.mapSize; }

void SoftMaps::checkBudget(ParamRegistry& r, const std::string& n, const int* samples) const {
  r.addCheck({n + "samples", n + "map_size"}, [this, n, samples](const ParamRegistry&) -> std::string {
    const std::uint64_t side = std::uint64_t(p_.mapSize), perMap = side * side * 4;  // 32-bit depth
    if (std::uint64_t(*samples) * perMap <= kBudgetBytes) return "";
    const std::uint64_t fit = kBudgetBytes / perMap;
    int largest = kMapSizes.front();
    for (int s : kMapSizes)
      if (std::uint64_t(*samples) * std::uint64_t(s) * std::uint64_t(s) * 4 <= kBudgetBytes) largest = s;
    return n + "samples = " + std::to_string(*samples) + " maps of " + n + "map_size = " + std::to_string(p_.mapSize) +
           " take " + std::to_string((std::uint64_t(*samples) * perMap) >> 20) + " MiB a light, over the " +
           std::to_string(kBudgetBytes >> 20) + " MiB budget of one light's maps: at " + std::to_string(p_.mapSize) +
           " at most " + std::to_string(fit) + " samples, or " + std::to_string(*samples) + " samples at " +
           std::to_string(largest) + " texels";
  });
}

void SoftMaps::init() {
  casters_.build();
  compare_ = gl::makeCompareSampler(true, label_ + ": compare linear");
  raw_ = gl::makeRawDepthSampler(label_ + ": raw depth");
  fbo_ = gl::makeFramebuffer(label_ + ": fbo");
  ensureArray(1, 1);  // something to bind before the first frame, and with every light off
}

void SoftMaps::ensureArray(int size, int layers) {
  if (array_ && size == arraySize_ && layers == arrayLayers_) return;
  array_ = gl::makeTexture(GL_TEXTURE_2D_ARRAY, label_ + ": maps");
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_.id());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
               nullptr);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  arraySize_ = size;
  arrayLayers_ = layers;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, array_.id(), 0, 0);
  glDrawBuffer(GL_NONE);  // depth only
  glReadBuffer(GL_NONE);
  gl::requireComplete(GL_FRAMEBUFFER, label_ + ": fbo");
}

// ==== 1. the light cameras: one at the sphere's centre per light, fitted to the scene =============
glm::mat4 faceView(const glm::vec3& position, int face) { return shadow::cubeFaceView(position, face); }

void SoftMaps::fit(const ShadowContext& c) {
  lights_.assign(std::min<std::size_t>(c.lights.size(), kMaxLights), {});
  const shadow::CasterBoxes boxes = c.scene.casterBoxes();
  int layer = 0;
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = c.lights[i];
    SoftLight& s = lights_[i];
    std::optional<Light> spot;
    bool cube = false;
    if (!light.enabled) s.why = "off";
    else if (light.kind == LightKind::Directional) s.why = "directional: a sphere needs a position";
    else if (light.kind == LightKind::Spot) spot = light;
    else if (!(spot = soft::spotCovering(light, c.scene.bounds()))) cube = true;
    if (!spot && !cube) continue;
    s.radius = light.area == AreaShape::Sphere ? light.radius : 0.0f;
    s.firstLayer = layer;
    if (cube) {
      fitCube(c, light, s);
      if (s.on) layer += 6 * int(samples_.size());
      continue;
    }
    const glm::vec2 range =
        soft::depthRange(shadow::lightViewAlong(spot->position, spot->direction), c.scene.bounds(), p_.minNear);
    s.nearZ = std::max(p_.minNear, range.x - s.radius);
    s.farZ = range.y + s.radius;
    s.casterNearZ = soft::nearestCasterDepth(shadow::lightViewAlong(spot->position, spot->direction), boxes.boxes,
                                             boxes.casts, s.nearZ);
    s.spot = *spot;
    s.centre = shadow::spotCamera(*spot, s.nearZ, s.farZ, boxes, true);
    s.tanHalfFov = std::tan(0.5f * shadow::spotFieldOfView(*spot));
    s.on = true;
    layer += int(samples_.size());
  }
}

shadow::LightCamera SoftMaps::faceCamera(const SoftLight& s, int face, const glm::vec3& position,
                                         const shadow::CasterBoxes& boxes) {
  shadow::LightCamera camera;
  camera.view = faceView(position, face);
  camera.projection = s.centre.projection;
  shadow::cullAgainst(camera, boxes, shadow::volumeFromViewProj(camera.viewProj()), true);
  return camera;
}

// A point light inside the scene: six faces around it, their depth range and nearest caster the
// widest of the six, each face's maps within the budget of one light's maps.
void SoftMaps::fitCube(const ShadowContext& c, const Light& light, SoftLight& s) const {
  const std::uint64_t side = std::uint64_t(mapSize()), bytes = 6 * samples_.size() * side * side * 4;
  if (bytes > kBudgetBytes) {
    s.why = "inside the scene: a cube of 6 x " + std::to_string(samples_.size()) + " maps of " + std::to_string(side) +
            "^2 takes " + std::to_string(bytes >> 20) + " MiB, over the " + std::to_string(kBudgetBytes >> 20) +
            " MiB budget of one light's maps";
    return;
  }
  if (cubeCheck_)
    if (std::string refused = cubeCheck_(mapSize()); !refused.empty()) {
      s.why = "inside the scene: " + refused;
      return;
    }
  const shadow::CasterBoxes boxes = c.scene.casterBoxes();
  s.nearZ = std::numeric_limits<float>::max();
  s.farZ = 0.0f;
  for (int f = 0; f < 6; ++f) {
    const glm::vec2 range = soft::depthRange(faceView(light.position, f), c.scene.bounds(), p_.minNear);
    s.nearZ = std::min(s.nearZ, range.x);
    s.farZ = std::max(s.farZ, range.y);
  }
  s.nearZ = std::max(p_.minNear, s.nearZ - s.radius);
  s.farZ = std::max(s.farZ + s.radius, s.nearZ + 0.1f);
  s.casterNearZ = std::numeric_limits<float>::max();
  for (int f = 0; f < 6; ++f)
    s.casterNearZ = std::min(s.casterNearZ,
                             soft::nearestCasterDepth(faceView(light.position, f), boxes.boxes, boxes.casts, s.nearZ));
  s.faces = 6;
  s.spot = light;
  s.tanHalfFov = kCubeTanHalfFov;
  s.centre.view = glm::translate(glm::mat4(1.0f), -light.position);
  s.centre.projection = glm::perspective(2.0f * std::atan(kCubeTanHalfFov), 1.0f, s.nearZ, s.farZ);
  s.on = true;
}

// ==== 2. the depth passes: one map per light and sample point on its sphere ======================
void SoftMaps::render(const ShadowContext& c, const std::vector<glm::vec3>& samples, ShadowStats& stats,
                      bool renderMaps) {
  samples_.assign(samples.begin(), samples.begin() + std::min<std::size_t>(samples.size(), kMaxSamples));
  if (samples_.empty()) samples_.push_back(glm::vec3(0.0f));
  fit(c);
  for (std::size_t i = 0; i < lights_.size(); ++i)
    if (!lights_[i].on && c.lights[i].enabled)
      stats.extra.push_back({"light" + std::to_string(i), "no soft shadow (" + lights_[i].why + ")"});
    else if (lights_[i].faces == 6)
      stats.extra.push_back({"light" + std::to_string(i),
                             "a cube: 6 faces inside the scene, " + std::to_string(6 * samples_.size()) + " maps"});
  if (!renderMaps) return;
  int layers = 0;
  for (const SoftLight& s : lights_) layers += s.on ? s.faces * int(samples_.size()) : 0;
  const int size = mapSize();
  ensureArray(layers > 0 ? size : 1, std::max(layers, 1));
  const shadow::CasterBoxes boxes = c.scene.casterBoxes();
  // Every sample's camera first: what the maps depend on, with the scene and the pass's settings.
  std::vector<shadow::LightCamera> cameras;
  PassKey key;
  key << c.scene.revision() << size << arrayLayers_ << p_.offsetFactor << p_.offsetUnits;
  for (const SoftLight& s : lights_) {
    if (!s.on) continue;
    for (int f = 0; f < s.faces; ++f) {
      const glm::mat3 toWorld = glm::transpose(glm::mat3(s.faces == 6 ? faceView(s.spot.position, f) : s.centre.view));
      Light moved = s.spot;  // same axis and cone: the same rotation, moved by R s_k
      for (const glm::vec3& sample : samples_) {
        moved.position = s.spot.position + toWorld * (s.radius * sample);
        cameras.push_back(s.faces == 1 ? shadow::spotCamera(moved, s.nearZ, s.farZ, boxes, true)
                                       : faceCamera(s, f, moved.position, boxes));
        key << s.firstLayer << cameras.back().viewProj() << std::span<const char>(cameras.back().casters);
        stats.culledCasters += cameras.back().culled;
      }
    }
  }
  stats.bytes += std::uint64_t(arraySize_) * std::uint64_t(arraySize_) * std::uint64_t(arrayLayers_) * 4;
  const MapPass pass(c, stats, -1, p_.reuseMaps, std::move(key), rendered_, drawn_, int(cameras.size()));
  if (!pass.draw()) return;
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(p_.offsetFactor, p_.offsetUnits);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size, size);
  glDepthMask(GL_TRUE);
  CasterOptions options;
  std::size_t next = 0;
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const SoftLight& s = lights_[i];
    if (!s.on) continue;
    auto t = gl::TimerScope(c.timers, "shadow light" + std::to_string(i));
    for (int k = 0; k < s.faces * int(samples_.size()); ++k) {
      const shadow::LightCamera& camera = cameras[next++];
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, array_.id(), 0, s.firstLayer + k);
      glClear(GL_DEPTH_BUFFER_BIT);
      stats.triangles += casters_.draw(c.scene, camera.viewProj(), camera.casters, options);
      stats.texels += std::uint64_t(size) * std::uint64_t(size);
    }
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
}

// ==== 3. what the visibility shaders read (shaders/05_soft_shadows/soft_maps.glsl) ========================
void SoftMaps::bind(const gl::Program& p, int unit) const {
  for (int i = 0; i < kMaxLights; ++i) {
    const SoftLight* s = i < int(lights_.size()) && lights_[std::size_t(i)].on ? &lights_[std::size_t(i)] : nullptr;
    const std::string n = "[" + std::to_string(i) + "]";
    p.set(("uSoftLayer" + n).c_str(), s ? s->firstLayer : -1);
    if (!s) continue;
    p.set(("uSoftFaces" + n).c_str(), s->faces);
    p.set(("uSoftView" + n).c_str(), s->centre.view);
    p.set(("uSoftRadius" + n).c_str(), s->radius);
    p.set(("uSoftTanHalfFov" + n).c_str(), s->tanHalfFov);
    p.set(("uSoftDepthRange" + n).c_str(), glm::vec2(s->nearZ, s->farZ));
    p.set(("uSoftCasterNear" + n).c_str(), s->casterNearZ);
  }
  for (std::size_t k = 0; k < samples_.size(); ++k)
    p.set(("uSoftSamples[" + std::to_string(k) + "]").c_str(), samples_[k]);
  p.set("uSoftSampleCount", int(samples_.size()));
  for (int f = 0; f < 6; ++f)
    p.set(("uSoftFaceTurn[" + std::to_string(f) + "]").c_str(), glm::mat3(faceView(glm::vec3(0.0f), f)));
  p.set("uSoftMapSize", float(mapSize()));
  p.set("uSoftBias", p_.bias);
  p.set("uSoftSlopeBias", p_.slopeBias);
  p.set("uSoftNormalOffset", p_.normalOffset);
  p.set("uSoftCardSlopeBias", p_.cardSlopeBias);
  p.set("uSoftCardNormalOffset", p_.cardNormalOffset);
  p.set("uSoftMaps", unit);
  p.set("uSoftDepths", unit + 1);
  for (int u = 0; u < 2; ++u) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit + u));
    glBindTexture(GL_TEXTURE_2D_ARRAY, array_.id());
    glBindSampler(GLuint(unit + u), u == 0 ? compare_.id() : raw_.id());
  }
  glActiveTexture(GL_TEXTURE0);
}

void SoftMaps::unbind(int unit) const {
  for (int u = unit; u < unit + 2; ++u) glBindSampler(GLuint(u), 0);
}

void SoftMaps::pushShapes(const ShadowContext& c) const {
  for (const SoftLight& s : lights_)
    if (s.on) {
      for (int f = 0; f < s.faces; ++f)
        c.debug.frustum(s.faces == 1 ? s.centre.viewProj() : s.centre.projection * faceView(s.spot.position, f),
                        kFrustumColour);
      c.debug.name(kFrustumColour, "a light's frustum, from the sphere's centre (a cube's six inside the scene)");
    }
}

}  // namespace shadowlab::tech

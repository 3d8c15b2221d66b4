#include "uniform_maps.hpp"

#include <string>

#include "algorithms/psm/post_shapes.hpp"
#include "technique/map_pass.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

void UniformShadowMaps::declare(ParamRegistry& r, const std::string& n) {
  declareMapSize(r, n + "map_size", &p_.mapSize, "directional and spot map resolution (texels per side)");
  declareMapSize(r, n + "cube_size", &p_.cubeSize, "point light cube-map face resolution (texels per side)");
  r.addChoice(n + "format", &p_.format, {"16", "24", "32f"}, "depth format of every map");
  r.addChoice(n + "filter", &p_.filter, {"nearest", "hardware_2x2", "pcf_nxn", "poisson"},
              "one comparison, GL_LINEAR compare (2x2), N x N taps, or 16 rotated Poisson taps");
  r.add(n + "pcf.size", &p_.pcfSize, 1, 9, "N of the N x N kernel (odd)");
  r.addCheck({n + "pcf.size"}, [this, name = n + "pcf.size"](const ParamRegistry&) {
    if (p_.pcfSize % 2 == 1) return std::string();  // an even N has no centre tap
    return name + " = " + std::to_string(p_.pcfSize) + ": the N x N kernel needs an odd N; valid: 1, 3, 5, 7, 9";
  });
  r.add(n + "pcf.radius", &p_.poissonRadius, 0.5f, 8, "Poisson disk radius in texels");
  declareBias(r, n, p_);
  r.add(n + "bias.receiver_plane", &p_.receiverPlane, "filter taps follow the receiver's plane (no PCF acne)");
  declareFitting(r, n, p_);
  r.add(n + "skip_faces", &p_.skipFaces, "skip cube faces whose frustum misses the view frustum");
  r.add(n + "cube.near", &p_.cubeNear, 0.01f, 10, "cube faces' near plane");
  r.add(n + "cube.far", &p_.cubeFar, 1, 500, "cube faces' far plane: beyond it, lit");
  declareSpotRange(r, n, p_);
  r.add(n + "reuse_maps", &p_.reuseMaps, "keep a map nothing invalidated (light, casters, light camera unchanged)");
}

void UniformShadowMaps::init() {
  casters_.build();
  compareNearest_ = gl::makeCompareSampler(false, "uniform maps: compare nearest");
  compareLinear_ = gl::makeCompareSampler(true, "uniform maps: compare linear (2x2 PCF)");
  dummy2D_ = gl::makeShadowMap(1, gl::DepthFormat::Depth16, "uniform maps: no 2D map");
  dummyCube_ = gl::makeShadowCube(1, gl::DepthFormat::Depth16, "uniform maps: no cube map");
}

const gl::ShadowMap* UniformShadowMaps::map2D(int light) const {
  if (light < 0 || light >= int(lights_.size())) return nullptr;
  const PerLight& l = lights_[std::size_t(light)];
  return l.type == Type::Ortho || l.type == Type::Perspective ? &l.map : nullptr;
}

const shadow::LightCamera* UniformShadowMaps::camera(int light) const {
  return map2D(light) ? &lights_[std::size_t(light)].camera : nullptr;
}

// ==== 1. the light cameras: fit, cull, skip (GL-free, algorithms/light_cameras) =================
void UniformShadowMaps::fitLight(const ShadowContext& c, int i, const shadow::ConvexVolume& view) {
  const Light& light = c.lights[std::size_t(i)];
  PerLight& l = lights_[std::size_t(i)];
  const shadow::CasterBoxes boxes = c.scene.casterBoxes();
  l.type = !light.enabled                         ? Type::None
           : light.kind == LightKind::Directional ? Type::Ortho
           : light.kind == LightKind::Spot        ? Type::Perspective
                                                  : Type::Cube;
  const int size = l.type == Type::Cube ? p_.cubeSize : p_.mapSize;
  if (l.type == Type::None) {
    l.map = {};
    l.rendered.clear();
    return;
  }
  if (l.map.size != size || l.map.format != p_.format || l.map.cube != (l.type == Type::Cube)) {
    l.rendered.clear();
    l.map = l.type == Type::Cube ? gl::makeShadowCube(size, p_.format, "light" + std::to_string(i) + " cube map")
                                 : gl::makeShadowMap(size, p_.format, "light" + std::to_string(i) + " shadow map");
  }
  if (l.type == Type::Cube) {
    l.faces = shadow::cubeCameras(light.position, p_.cubeNear, p_.cubeFar, boxes, view, p_.cullCasters, p_.skipFaces);
    return;
  }
  const shadow::Map2DCamera m = shadow::fitMap2D(
      light, boxes, view, directionalFit(p_, size, student.casterTest, student.fitter), p_.spotNear, p_.spotFar);
  l.camera = m.camera;
  l.texel = m.texel;
  l.textureMatrix = m.textureMatrix;
}

// What light i's map depends on: its cameras and the casters they keep, the scene, the depth pass's
// settings. A static light over a static scene (and a sun fitted to an unmoving view) keeps it.
PassKey UniformShadowMaps::passKey(const ShadowContext& c, const PerLight& l) const {
  PassKey key;
  key << c.scene.revision() << l.map.size << l.map.format << p_.offsetFactor << p_.offsetUnits << p_.cullFront;
  if (l.type != Type::Cube) return key << l.camera.viewProj() << std::span<const char>(l.camera.casters);
  for (const shadow::LightCamera& f : l.faces) key << f.skipped << f.viewProj() << std::span<const char>(f.casters);
  return key;
}

// ==== 2. the depth passes: one per 2D map, one per cube face that is not skipped ================
void UniformShadowMaps::renderLight(const ShadowContext& c, int i) {
  PerLight& l = lights_[std::size_t(i)];
  if (l.type == Type::None) return;
  // What the light cameras left out, whether or not the map is drawn again.
  if (l.type != Type::Cube) stats_.culledCasters += l.camera.culled;
  for (const shadow::LightCamera& f : l.faces)
    if (l.type == Type::Cube) f.skipped ? ++stats_.skippedFaces : stats_.culledCasters += f.culled;
  const MapPass pass(c, stats_, i, p_.reuseMaps, passKey(c, l), l.rendered, l.drawn);
  if (!pass.draw()) return;  // kept: nothing it depends on changed
  const CasterOptions options{true, p_.cullFront};
  const std::uint64_t side = std::uint64_t(l.map.size);
  if (l.type != Type::Cube) {
    gl::beginShadowPass(l.map);
    stats_.triangles += casters_.draw(c.scene, l.camera.viewProj(), l.camera.casters, options);
    stats_.texels += side * side;
    return;
  }
  for (int face = 0; face < 6; ++face) {
    const shadow::LightCamera& f = l.faces[std::size_t(face)];
    gl::beginShadowPass(l.map, face);  // a skipped face is cleared: lit, never stale
    if (f.skipped) continue;
    stats_.triangles += casters_.draw(c.scene, f.viewProj(), f.casters, options);
    stats_.texels += side * side;
  }
}

void UniformShadowMaps::render(const ShadowContext& c) {
  fitLights(c);
  renderDepth(c);
}

void UniformShadowMaps::fitLights(const ShadowContext& c) {
  lights_.resize(c.lights.size());
  const shadow::ConvexVolume view = shadow::volumeFromViewProj(c.viewerViewProj());
  stats_ = {};
  for (int i = 0; i < int(c.lights.size()); ++i) fitLight(c, i, view);
}

void UniformShadowMaps::renderDepth(const ShadowContext& c) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);  // every depth a little further from the light: less acne
  glPolygonOffset(p_.offsetFactor, p_.offsetUnits);
  for (int i = 0; i < int(lights_.size()); ++i) renderLight(c, i);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
  countMemory();
}

// The header's figures: the maps' memory, and the sun's texel in world units.
void UniformShadowMaps::countMemory() {
  for (int i = 0; i < int(lights_.size()); ++i) {
    const PerLight& l = lights_[std::size_t(i)];
    if (l.type != Type::None)
      stats_.bytes +=
          std::uint64_t(l.map.size) * l.map.size * (l.type == Type::Cube ? 6 : 1) * depthBytes(l.map.format);
    if (l.type == Type::Ortho)
      stats_.extra.push_back(
          {"light" + std::to_string(i) + " texel", std::to_string(l.texel * 100.0f).substr(0, 5) + " cm"});
  }
}

void UniformShadowMaps::pushShapes(const ShadowContext& c) const {
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const PerLight& l = lights_[i];
    const glm::vec4 colour = lightColour(i);
    if (l.type == Type::Ortho || l.type == Type::Perspective) c.debug.frustum(l.camera.viewProj(), colour);
    if (l.type == Type::Cube) c.debug.cross(c.lights[i].position, 0.5f, colour);
    if (l.type != Type::None)
      c.debug.name(colour, "light" + std::to_string(i) +
                               (l.type == Type::Cube ? "'s cube map (a cross at the light)" : "'s map"));
  }
  if (p_.fit == Fit::View) {
    c.debug.box(c.scene.bounds(), {0.4f, 0.4f, 0.4f, 1.0f});
    c.debug.name({0.4f, 0.4f, 0.4f, 1.0f}, "the scene's bounds");
  }
}

// The lit program specialised for this frame: each light's kind of map, the filter, its size.
std::vector<std::string> UniformShadowMaps::shaderDefines() const {
  std::string types;
  for (int i = 0; i < kMaxLights; ++i)
    types +=
        std::string(i ? ", " : "") + std::to_string(i < int(lights_.size()) ? int(lights_[std::size_t(i)].type) : 0);
  std::vector<std::string> defines{"SHADOW_TYPES " + types, "SHADOW_FILTER " + std::to_string(int(p_.filter)),
                                   "PCF_SIZE " + std::to_string(p_.pcfSize),
                                   std::string("RECEIVER_PLANE ") + (p_.receiverPlane ? "1" : "0")};
  if (student.glslPcf) defines.push_back("SHADOWLAB_STUDENT_PCF");
  return defines;
}

// ==== 3. what the lit pass reads: per light its matrix, texel size and map ======================
void UniformShadowMaps::bindVisibility(const gl::Program& lit, int firstUnit) const {
  lit.set("uCubeNear", p_.cubeNear);
  lit.set("uCubeFar", std::max(p_.cubeFar, p_.cubeNear + 0.1f));
  lit.set("uFilter", int(p_.filter));
  lit.set("uPcfSize", p_.pcfSize);  // odd: declare()'s check refuses an even N
  lit.set("uPoissonRadius", p_.poissonRadius);
  setBiasUniforms(lit, p_);
  lit.set("uReceiverPlane", p_.receiverPlane);
  const bool nearest = p_.filter == Filter::Nearest || p_.filter == Filter::BoxNxN;
  const GLuint sampler = nearest ? compareNearest_.id() : compareLinear_.id();
  for (int i = 0; i < kMaxLights; ++i) {
    const PerLight* l = i < int(lights_.size()) ? &lights_[std::size_t(i)] : nullptr;
    const Type type = l ? l->type : Type::None;
    const std::string n = "[" + std::to_string(i) + "]";
    lit.set(("uShadowType" + n).c_str(), int(type));
    if (type != Type::None) {
      lit.set(("uShadowMatrix" + n).c_str(), l->textureMatrix);
      lit.set(("uShadowTexel" + n).c_str(), l->texel);
      lit.set(("uShadowSize" + n).c_str(), float(l->map.size));
    }
    const int unit2D = firstUnit + i, unitCube = firstUnit + kMaxLights + i;
    lit.set(("uShadowMap" + std::to_string(i)).c_str(), unit2D);
    lit.set(("uShadowCube" + std::to_string(i)).c_str(), unitCube);
    const bool cube = type == Type::Cube, flat = type == Type::Ortho || type == Type::Perspective;
    glActiveTexture(GLenum(GL_TEXTURE0 + unit2D));
    glBindTexture(GL_TEXTURE_2D, flat ? l->map.texture.id() : dummy2D_.texture.id());
    glBindSampler(GLuint(unit2D), sampler);
    glActiveTexture(GLenum(GL_TEXTURE0 + unitCube));
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube ? l->map.texture.id() : dummyCube_.texture.id());
    glBindSampler(GLuint(unitCube), sampler);
  }
  glActiveTexture(GL_TEXTURE0);
}

void UniformShadowMaps::describePostProjective(const ShadowContext& c, int light,
                                               psm::PostProjectiveShapes& out) const {
  if (const shadow::LightCamera* cam = camera(light))
    out.worldFrustum(postProjectiveCamera(c, light), glm::dmat4(cam->viewProj()), lightColour(std::size_t(light)));
}

void UniformShadowMaps::unbindVisibility(int firstUnit) const {
  for (int u = firstUnit; u < firstUnit + 2 * kMaxLights; ++u) glBindSampler(GLuint(u), 0);
}

}  // namespace shadowlab::tech

#include "projective_maps.hpp"

#include <string>

#include "algorithms/psm/bias.hpp"
#include "gl/caps.hpp"
#include "algorithms/psm/receivers.hpp"
#include "technique/map_pass.hpp"
#include "technique/map_settings.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

std::string indexed(const char* name, int i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

// Both faces of every caster (see CasterOptions::cull): alpha-tested cards still discard their holes.
const CasterOptions kNoCulling{.alphaTest = true, .cullFront = false, .cull = false};

}  // namespace

std::span<const Aabb> ReceiverVolumes::get(const SceneCache& scene, int tiles) {
  if (revision_ != scene.revision() || tiles_ != tiles) {
    boxes_ = psm::receiverVolumes(scene.scene(), tiles);
    revision_ = scene.revision();
    tiles_ = tiles;
  }
  return boxes_;
}

int selectCasters(const SceneCache& scene, const psm::Frustum& view, const glm::dvec4& light, bool cull,
                  std::vector<char>& keep) {
  const int kept = psm::potentialCasters(scene.boxes(), scene.casts(), view, light, keep);
  if (cull) {
    int casters = 0;
    for (const char k : scene.casts()) casters += k != 0;
    return casters - kept;
  }
  keep.assign(scene.casts().begin(), scene.casts().end());
  return 0;
}

void ProjectiveMapSet::declare(ParamRegistry& r, const std::string& n) {
  declareMapSize(r, n + "map_size", &p_.mapSize,
                 "each light's texel budget is this squared: one map, or a face set sharing it");
  r.addChoice(n + "format", &p_.format, {"16", "24", "32f"}, "depth format (the paper: 24 bits suffice)");
  r.addChoice(n + "filter", &p_.filter, {"nearest", "hardware_2x2"}, "one comparison, or GL_LINEAR compare (2x2 PCF)");
  r.addChoice(n + "bias", &p_.bias, {"constant", "world"},
              "constant depth bias, or the world-space texel-size bias a + b L_texel (fix 4)");
  r.add(n + "bias.constant", &p_.constantBias, 0, 0.05f, "window-depth units subtracted before the comparison");
  r.add(n + "bias.a", &p_.worldA, 0, 1, "a: world units every caster moves away from the light");
  r.add(n + "bias.b", &p_.worldB, 0, 8, "b: times the world size of one texel where the caster is");
  r.add(n + "bias.max", &p_.worldMax, 0, 10, "the most a caster moves (one texel can be unbounded near infinity)");
  r.add(n + "bias.normal_offset", &p_.normalOffset, 0, 4,
        "the lookup moves this many texels along N (their world size at the point), more at grazing light");
  r.add(n + "bias.receiver_plane", &p_.receiverPlane,
        "each tap compares against the receiver's plane at its texel (depth slope from screen derivatives)");
  r.add(n + "bias.plane_normal_offset", &p_.planeNormalOffset, 0, 4,
        "with the receiver plane: the normal offset in texels where the facet faces the light");
  r.add(n + "offset.factor", &p_.slopeOffset, 0, 10,
        "glPolygonOffset factor in the depth pass: the depth slope of each caster in the map itself");
  r.add(n + "reuse_maps", &p_.reuseMaps,
        "keep a light's maps nothing invalidated (light, casters, the maps' matrices unchanged: a still camera)");
}

void ProjectiveMapSet::init() {
  casters_.build();
  layersView_.build();
  compareNearest_ = gl::makeCompareSampler(false, "projective maps: compare nearest");
  compareLinear_ = gl::makeCompareSampler(true, "projective maps: compare linear (2x2 PCF)");
  raw_ = gl::makeRawDepthSampler("projective maps: raw");
  emptyVao_ = gl::makeVertexArray("projective maps: layers view");
  dummy_ = gl::makeTexture(GL_TEXTURE_2D_ARRAY, "projective maps: no map");
  glBindTexture(GL_TEXTURE_2D_ARRAY, dummy_.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT16, 1, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

int ProjectiveMapSet::totalSide() const { return p_.mapSize; }

// One array texture per light, reallocated only when its side or format changes or it needs more
// layers (a face set going from 3 to 5 faces), with a framebuffer whose depth is one layer.
void ProjectiveMapSet::ensureArray(PerLight& l, int light, int side, int layers) {
  if (l.array && l.side == side && l.format == p_.format && l.layers >= layers) return;
  const std::string label = "light" + std::to_string(light) + " projective maps";
  l.array = gl::makeTexture(GL_TEXTURE_2D_ARRAY, label);
  ++l.generation;
  l.side = side;
  l.layers = layers;
  l.format = p_.format;
  glBindTexture(GL_TEXTURE_2D_ARRAY, l.array.id());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  const GLenum type = p_.format == gl::DepthFormat::Depth32F ? GL_FLOAT : GL_UNSIGNED_INT;
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GLint(gl::depthInternalFormat(p_.format)), side, side, layers, 0,
               GL_DEPTH_COMPONENT, type, nullptr);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  l.fbo = gl::makeFramebuffer(label + " fbo");
  glBindFramebuffer(GL_FRAMEBUFFER, l.fbo.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, l.array.id(), 0, 0);
  glDrawBuffer(GL_NONE);  // depth only
  glReadBuffer(GL_NONE);
  gl::requireComplete(GL_FRAMEBUFFER, label);
}

// Fix 4 for the reference: the factors of K and the light, for depth_psm.vert.
void ProjectiveMapSet::setBiasUniforms(const glm::dmat4& worldToClip, int side, const glm::dvec4& worldLight) {
  const bool world = p_.bias == ProjectiveBias::WorldTexel;
  const psm::TexelStep step = world ? psm::texelStepFactors(worldToClip, glm::dvec2(double(side))) : psm::TexelStep{};
  casters_.setUniforms([&](const gl::Program& p) {
    p.set("uSlopeOffset", p_.slopeOffset);  // depth_psm.frag, without GL_DEPTH_CLAMP
    p.set("uWorldBias", world);
    if (!world) return;
    p.set("uTexelStep", glm::vec4(step.u));
    p.set("uClipW", glm::vec4(step.r));
    p.set("uLightWorld", glm::vec4(worldLight));
    p.set("uBiasA", p_.worldA);
    p.set("uBiasB", p_.worldB);
    p.set("uBiasMax", p_.worldMax);
  });
}

void ProjectiveMapSet::disable(int light) {
  lights_[std::size_t(light)].used = 0;
  lights_[std::size_t(light)].faces = {};
}

void ProjectiveMapSet::render(const ShadowContext& c, int light, std::span<const ProjectiveMapView> maps, int side,
                              std::span<const char> keep, const glm::dvec4& worldLight, const FaceLookup& faces,
                              ShadowStats& stats) {
  PerLight& l = lights_[std::size_t(light)];
  l.used = int(std::min<std::size_t>(maps.size(), kPsmMaps));
  l.faces = faces;
  if (l.used == 0) return;
  ensureArray(l, light, side, l.used);
  stats.bytes += std::uint64_t(l.side) * std::uint64_t(l.side) * std::uint64_t(l.layers) * depthBytes(l.format);
  const MapPass pass(c, stats, light, p_.reuseMaps,
                     passKey(c, l, maps.first(std::size_t(l.used)), side, keep, worldLight), l.rendered, l.drawn);
  if (!pass.draw()) return;  // kept: nothing it depends on changed
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Casters nearer than the near plane (or, for the inverse projection, far behind the camera at
  // depth below -1) still shade: clamp their depth instead of clipping them (without GL_DEPTH_CLAMP,
  // depth_psm.frag clamps it per fragment).
  const bool depthClamp = gl::caps().depthClamp;
  if (depthClamp) glEnable(GL_DEPTH_CLAMP);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(p_.slopeOffset, 0.0f);
  const bool biasOnCpu = student.worldBias && p_.bias == ProjectiveBias::WorldTexel;  // 09.4, lesson 09
  for (int k = 0; k < l.used; ++k) {
    glBindFramebuffer(GL_FRAMEBUFFER, l.fbo.id());
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, l.array.id(), 0, k);
    glViewport(0, 0, side, side);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::dmat4& m = maps[std::size_t(k)].worldToClip;
    l.matrices[std::size_t(k)] = glm::mat4(m);
    const psm::TexelStep step = psm::texelStepFactors(m, glm::dvec2(double(side)));
    l.texelStep[std::size_t(k)] = glm::vec4(step.u);
    l.clipW[std::size_t(k)] = glm::vec4(step.r);
    const std::span<const char> drawn = maps[std::size_t(k)].keep.empty() ? keep : maps[std::size_t(k)].keep;
    if (biasOnCpu) {
      stats.triangles +=
          student.worldBias({c, m, side, drawn, worldLight, p_.worldA, p_.worldB, kNoCulling, p_.slopeOffset});
    } else {
      setBiasUniforms(m, side, worldLight);
      stats.triangles += casters_.draw(c.scene, l.matrices[std::size_t(k)], drawn, kNoCulling);
    }
    stats.texels += std::uint64_t(side) * std::uint64_t(side);
  }
  if (depthClamp) glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
}

// What light `l`'s maps depend on: the scene, the array they live in, the depth pass's settings
// (fix 4's bias and the light it pushes away from, or a student's), and per map its matrix and the
// casters it draws. Still camera, still light, static scene: the same key, the maps stay.
PassKey ProjectiveMapSet::passKey(const ShadowContext& c, const PerLight& l, std::span<const ProjectiveMapView> maps,
                                  int side, std::span<const char> keep, const glm::dvec4& worldLight) const {
  PassKey key;
  key << c.scene.revision() << l.generation << side << p_.format << p_.bias << p_.worldA << p_.worldB << p_.worldMax
      << p_.slopeOffset << bool(student.worldBias) << worldLight << maps.size() << keep;
  for (const ProjectiveMapView& m : maps) key << m.worldToClip << m.keep;
  return key;
}

bool ProjectiveMapSet::anyFaces() const {
  for (const PerLight& l : lights_)
    if (l.used > 0 && l.faces.faces) return true;
  return false;
}

std::vector<std::string> ProjectiveMapSet::shaderDefines() const {
  std::vector<std::string> defines;
  if (anyFaces()) defines.push_back("PSM_FACES");
  if (p_.normalOffset > 0 || (p_.receiverPlane && p_.planeNormalOffset > 0)) defines.push_back("PSM_NORMAL_OFFSET");
  if (p_.receiverPlane)
    defines.push_back(p_.filter == ProjectiveFilter::Hardware2x2 ? "PSM_RECEIVER_PLANE 2" : "PSM_RECEIVER_PLANE 1");
  if (student.glslLookup) defines.push_back("SHADOWLAB_STUDENT_PSM_LOOKUP");
  if (student.glslFaces) defines.push_back("SHADOWLAB_STUDENT_PSM_FACES");
  return defines;
}

void ProjectiveMapSet::bind(const gl::Program& lit, int firstUnit) const {
  lit.set("uPsmConstantBias", p_.bias == ProjectiveBias::Constant ? p_.constantBias : 0.0f);
  lit.set("uPsmNormalOffset", p_.normalOffset);
  lit.set("uPsmPlaneNormalOffset", p_.planeNormalOffset);
  lit.set("uPsmOffsetMax", p_.worldMax);
  // The receiver plane filters its own 2x2 taps, each with its own reference depth.
  const bool linear = p_.filter == ProjectiveFilter::Hardware2x2 && !p_.receiverPlane;
  const GLuint sampler = linear ? compareLinear_.id() : compareNearest_.id();
  for (int i = 0; i < kPsmLights; ++i) {
    const PerLight& l = lights_[std::size_t(i)];
    lit.set(indexed("uPsmLayers", i).c_str(), l.used);
    lit.set(indexed("uPsmSize", i).c_str(), float(l.side));
    for (int k = 0; k < l.used; ++k) {
      lit.set(indexed("uPsmMatrix", i * kPsmMaps + k).c_str(), l.matrices[std::size_t(k)]);
      lit.set(indexed("uPsmTexelStep", i * kPsmMaps + k).c_str(), l.texelStep[std::size_t(k)]);
      lit.set(indexed("uPsmClipW", i * kPsmMaps + k).c_str(), l.clipW[std::size_t(k)]);
    }
    lit.set(indexed("uPsmFaces", i).c_str(), l.used > 0 && l.faces.faces);
    if (l.used > 0 && l.faces.faces) {
      lit.set(indexed("uPsmCamera", i).c_str(), glm::mat4(l.faces.cameraViewProj));
      lit.set(indexed("uPsmPostLight", i).c_str(), glm::vec4(l.faces.postLight));
      for (int f = 0; f < 6; ++f)
        lit.set(indexed("uPsmLayerOfFace", i * 6 + f).c_str(), l.faces.layerOfFace[std::size_t(f)]);
    }
    const int unit = firstUnit + i;
    lit.set(indexed("uPsmMaps", i).c_str(), unit);
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, l.used > 0 ? l.array.id() : dummy_.id());
    glBindSampler(GLuint(unit), sampler);
  }
  glActiveTexture(GL_TEXTURE0);
}

void ProjectiveMapSet::unbind(int firstUnit) const {
  for (int u = firstUnit; u < firstUnit + kPsmLights; ++u) glBindSampler(GLuint(u), 0);
}

void ProjectiveMapSet::drawLayers(int light, int x, int y, int w, int h) {
  const PerLight& l = lights_[std::size_t(light)];
  if (l.used == 0 || !layersView_.valid()) return;
  glViewport(x, y, w, h);
  glDisable(GL_DEPTH_TEST);
  layersView_.use();
  layersView_.set("uLayers", 7);
  layersView_.set("uCount", l.used);
  glActiveTexture(GL_TEXTURE7);
  glBindTexture(GL_TEXTURE_2D_ARRAY, l.array.id());
  glBindSampler(7, raw_.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(7, 0);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab::tech

#include "hybrid_maps.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "technique/map_pass.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

std::string kib(std::uint64_t bytes) { return std::to_string((bytes + 512) / 1024) + " KiB"; }

std::string percent(double part, double whole) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", whole > 0 ? 100.0 * part / whole : 0.0);
  return buf;
}

}  // namespace

HybridShadowMaps::HybridShadowMaps(HybridMapParams defaults) : p_(defaults) {}
HybridShadowMaps::~HybridShadowMaps() = default;

void HybridShadowMaps::declare(ParamRegistry& r, const std::string& n) {
  r.add(n + "map_size", &p_.mapSize, 16, 8192,
        "the full-resolution map the sweep starts from, texels per side (any size: equal-memory comparisons)");
  r.addChoice(n + "format", &p_.format, {"16", "24", "32f"}, "depth format of the full map (the paper: 16)");
  r.add(n + "levels", &p_.levels, 0, hybrid::kMaxLevels,
        "merge sweeps: 0 is a standard map, 2 the paper's (2048 -> 1024 -> 512 where the depth is smooth)");
  r.addChoice(n + "criterion", &p_.criterion, {"window", "linear", "slope"},
              "what the merge test reads: window depth (the paper), linear depth, or the depth's derivative");
  r.add(n + "eps0", &p_.eps0, 0, 1, "merge when |m - Dn| <= eps0 Dn for all four (the paper: 0.25; window, linear)");
  r.add(n + "max_slope", &p_.maxSlope, 0, 16, "slope criterion: merge planes with |dz/dx| + |dz/dy| up to this");
  r.addChoice(n + "build", &p_.build, {"gpu", "cpu"},
              "the sweep and the index as GPU passes, or on the CPU (the reference: read back, swept, uploaded)");
  r.addChoice(n + "filter", &p_.filter, {"nearest", "bilinear_2x2", "pcf_nxn"},
              "one comparison, four with bilinear weights, or N x N (every tap descends the index)");
  r.add(n + "pcf.size", &p_.pcfSize, 1, 9, "N of the N x N kernel (odd)");
  r.add(n + "reuse_maps", &p_.reuseMaps,
        "keep a hybrid map nothing invalidated (light, casters, light camera, sweep settings unchanged)");
  declareBias(r, n, p_);
  declareFitting(r, n, p_);
  declareSpotRange(r, n, p_);
}

void HybridShadowMaps::init() {
  casters_.build();
  builder_.init();
  levelsView_.build();
  levelsViewStudent_.setRequired([this] { return student.glslDescent; });
  levelsViewStudent_.build();
  vao_ = gl::makeVertexArray("hybrid maps: views");
  const std::uint32_t zero[4] = {0, 0, 0, 0};
  dummy_ = gl::makeTexture(GL_TEXTURE_2D, "hybrid maps: no map");
  glBindTexture(GL_TEXTURE_2D, dummy_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32UI, 1, 1, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, zero);
  glBindTexture(GL_TEXTURE_2D, 0);
}

const HybridMapGpu* HybridShadowMaps::map(int i) const {
  return i >= 0 && i < int(lights_.size()) && lights_[std::size_t(i)]->on ? &lights_[std::size_t(i)]->map : nullptr;
}
const gl::ShadowMap* HybridShadowMaps::depthMap(int i) const {
  return map(i) ? &lights_[std::size_t(i)]->depth : nullptr;
}
const shadow::Map2DCamera* HybridShadowMaps::camera(int i) const {
  return map(i) ? &lights_[std::size_t(i)]->camera : nullptr;
}

hybrid::MergeRule HybridShadowMaps::mergeRule(int i) const {
  hybrid::MergeRule rule;
  rule.criterion = p_.criterion;
  rule.eps0 = p_.eps0;
  rule.maxSlope = p_.maxSlope;
  if (const shadow::Map2DCamera* m = camera(i))
    rule.space = hybrid::depthSpaceOf(m->camera.projection, m->perspective, p_.mapSize, m->texel);
  return rule;
}

// ==== 1. the light cameras (GL-free, algorithms/light_cameras), as the uniform maps fit theirs ======
void HybridShadowMaps::fitLights(const ShadowContext& c) {
  stats_ = {};
  while (lights_.size() < c.lights.size()) lights_.push_back(std::make_unique<PerLight>());
  const shadow::ConvexVolume view = shadow::volumeFromViewProj(c.viewerViewProj());
  for (std::size_t i = 0; i < c.lights.size(); ++i) {
    const Light& light = c.lights[i];
    PerLight& l = *lights_[i];
    l.point = light.enabled && light.kind == LightKind::Point;
    l.on = light.enabled && !l.point;
    if (!l.on) continue;
    l.camera = shadow::fitMap2D(light, c.scene.casterBoxes(), view, directionalFit(p_, p_.mapSize, nullptr, nullptr),
                                p_.spotNear, p_.spotFar);
  }
  for (std::size_t i = c.lights.size(); i < lights_.size(); ++i) lights_[i]->on = lights_[i]->point = false;
}

// What light i's hybrid map depends on: its camera and the casters it keeps, the scene, the depth
// pass's settings and the sweep's. A static light over a static scene (a sun fitted to an unmoving
// view) keeps its map, and the three build passes are skipped with the depth pass.
PassKey HybridShadowMaps::passKey(const ShadowContext& c, const PerLight& l) const {
  PassKey key;
  key << c.scene.revision() << p_.mapSize << p_.format << p_.offsetFactor << p_.offsetUnits << p_.cullFront << p_.levels
      << p_.criterion << p_.eps0 << p_.maxSlope << p_.build << bool(student.sweep) << l.camera.camera.viewProj();
  return key << std::span<const char>(l.camera.camera.casters);
}

// ==== 2. the full-resolution depth maps: what a standard map renders, N x N =======================
void HybridShadowMaps::renderDepth(const ShadowContext& c) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(p_.offsetFactor, p_.offsetUnits);
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    PerLight& l = *lights_[i];
    if (!l.on) continue;
    stats_.culledCasters += l.camera.camera.culled;
    const MapPass pass(c, stats_, int(i), p_.reuseMaps && l.depth.size == p_.mapSize, passKey(c, l), l.rendered,
                       l.drawn);
    l.reused = !pass.draw();
    if (l.reused) continue;
    if (l.depth.size != p_.mapSize || l.depth.format != p_.format)
      l.depth = gl::makeShadowMap(p_.mapSize, p_.format, "light" + std::to_string(i) + " full-resolution map");
    gl::beginShadowPass(l.depth);
    stats_.triangles +=
        casters_.draw(c.scene, l.camera.camera.viewProj(), l.camera.camera.casters, {true, p_.cullFront});
    stats_.texels += std::uint64_t(p_.mapSize) * std::uint64_t(p_.mapSize);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void HybridShadowMaps::buildOnCpu(PerLight& l, const hybrid::MergeRule& rule) {
  const shadow::DepthMap depth = builder_.readDepth(l.depth);
  std::vector<hybrid::MergeGrid> grids = hybrid::mergeSweep(depth, rule, student.sweep ? 0 : p_.levels);
  for (int k = 1; student.sweep && k <= p_.levels; ++k) {
    // A student's sweep: its grid must be the next level's, or the index cannot be built from it.
    hybrid::MergeGrid next = student.sweep(grids.back(), rule, k);
    const int expected = hybrid::halvedSize(grids.back().size);
    if (next.size != expected || next.value.size() != std::size_t(expected) * std::size_t(expected))
      throw std::runtime_error("impl=student: sweepLevel returned a " + std::to_string(next.size) + "x" +
                               std::to_string(next.size) + " grid of " + std::to_string(next.value.size()) +
                               " values for level " + std::to_string(k) + "; expected " + std::to_string(expected) +
                               "x" + std::to_string(expected) + " (exercise 07.2)");
    grids.push_back(std::move(next));
  }
  HybridBuilder::upload(hybrid::buildHybrid(grids), l.map);
}

// ==== 3.-4. the merge sweep and the index (HybridBuilder's passes), or on the CPU ===================
void HybridShadowMaps::buildMaps(const ShadowContext& c) {
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    PerLight& l = *lights_[i];
    if (!l.on || l.reused) continue;
    const hybrid::MergeRule rule = mergeRule(int(i));
    const std::string suffix = " light" + std::to_string(i);
    if (p_.build == HybridPath::Cpu || student.sweep) {
      auto t = gl::TimerScope(c.timers, "hybrid cpu build" + suffix);
      buildOnCpu(l, rule);
    } else {
      builder_.build(l.depth, rule, p_.levels, l.map, &c.timers, suffix);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
  for (std::size_t i = 0; i < lights_.size(); ++i)
    if (lights_[i]->on || lights_[i]->point) pushStats(int(i), *lights_[i]);
}

// The header's figures for light i: what the map stores against the full map, and where.
void HybridShadowMaps::pushStats(int i, const PerLight& l) {
  const std::string n = "light" + std::to_string(i);
  if (l.point) {
    stats_.extra.push_back({n, "point light: no hybrid map (unshadowed)"});
    return;
  }
  const HybridMapGpu& m = l.map;
  const std::uint64_t full = std::uint64_t(m.sourceSize) * std::uint64_t(m.sourceSize);
  const std::uint64_t root = std::uint64_t(m.rootSize) * std::uint64_t(m.rootSize);
  const std::uint64_t stored = root + 3 * std::uint64_t(m.recordCount);  // each record: one word becomes four
  const std::uint64_t fullBytes = full * depthBytes(l.depth.format);
  stats_.bytes += m.storedBytes() + m.workBytes + fullBytes;
  stats_.extra.push_back({n + " stored texels", std::to_string(stored) + " of " + std::to_string(full) + " (" +
                                                    percent(double(stored), double(full)) + ")"});
  stats_.extra.push_back({n + " hybrid bytes", std::to_string(m.storedBytes()) + " (root " + kib(4 * root) +
                                                   " + index " + kib(m.storedBytes() - 4 * root) + ")"});
  stats_.extra.push_back({n + " full map bytes", std::to_string(fullBytes) + " (" +
                                                     percent(double(m.storedBytes()), double(fullBytes)) +
                                                     " stored; build work " + kib(m.workBytes) + ")"});
  std::string records = std::to_string(m.recordCount);
  for (int k = 1; k <= m.levels; ++k)
    records += (k == 1 ? " (L" : ", L") + std::to_string(k) + " " + std::to_string(m.recordsAt[std::size_t(k)]);
  stats_.extra.push_back({n + " records", records + (m.levels > 0 ? ")" : "")});
}

void HybridShadowMaps::pushShapes(const ShadowContext& c) const {
  for (std::size_t i = 0; i < lights_.size(); ++i)
    if (lights_[i]->on) {
      c.debug.frustum(lights_[i]->camera.camera.viewProj(), lightColour(i));
      c.debug.name(lightColour(i), "light" + std::to_string(i) + "'s map");
    }
  if (p_.fit == Fit::View) {
    c.debug.box(c.scene.bounds(), {0.4f, 0.4f, 0.4f, 1.0f});
    c.debug.name({0.4f, 0.4f, 0.4f, 1.0f}, "the scene's bounds");
  }
}

void HybridShadowMaps::render(const ShadowContext& c) {
  fitLights(c);
  renderDepth(c);
  buildMaps(c);
}

// ==== 5. what the lit pass reads: per light its matrix, texel size, levels, root and records ========
std::vector<std::string> HybridShadowMaps::shaderDefines() const {
  std::vector<std::string> defines{"HYBRID_FILTER " + std::to_string(int(p_.filter))};
  if (student.glslDescent) defines.push_back("SHADOWLAB_STUDENT_DESCENT");
  return defines;
}

void HybridShadowMaps::bindLight(const gl::Program& p, int i, int unitRoot, int unitRecords) const {
  const HybridMapGpu* m = map(i);
  const std::string n = "[" + std::to_string(i) + "]";
  const bool perspective = m && lights_[std::size_t(i)]->camera.perspective;
  p.set(("uHybridType" + n).c_str(), !m ? 0 : perspective ? 2 : 1);
  if (m) {
    const shadow::Map2DCamera& cam = lights_[std::size_t(i)]->camera;
    p.set(("uHybridMatrix" + n).c_str(), cam.textureMatrix);
    p.set(("uHybridTexel" + n).c_str(), cam.texel);
    p.set(("uHybridSize" + n).c_str(), m->sourceSize);
    p.set(("uHybridLevels" + n).c_str(), m->levels);
  }
  p.set(("uHybridRoot" + n).c_str(), unitRoot);
  p.set(("uHybridRecords" + n).c_str(), unitRecords);
  glActiveTexture(GLenum(GL_TEXTURE0 + unitRoot));
  glBindTexture(GL_TEXTURE_2D, m ? m->root.id() : dummy_.id());
  glBindSampler(GLuint(unitRoot), 0);
  glActiveTexture(GLenum(GL_TEXTURE0 + unitRecords));
  glBindTexture(GL_TEXTURE_2D, m && m->records ? m->records.id() : dummy_.id());
  glBindSampler(GLuint(unitRecords), 0);
}

void HybridShadowMaps::bindVisibility(const gl::Program& lit, int firstUnit) const {
  setBiasUniforms(lit, p_);
  lit.set("uPcfSize", p_.pcfSize | 1);  // an even N has no centre tap: the next odd one
  for (int i = 0; i < kMaxLights; ++i) bindLight(lit, i, firstUnit + i, firstUnit + kMaxLights + i);
  glActiveTexture(GL_TEXTURE0);
}

void HybridShadowMaps::unbindVisibility(int firstUnit) const {
  for (int u = firstUnit; u < firstUnit + 2 * kMaxLights; ++u) {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

// ==== views ==========================================================================================
void HybridShadowMaps::drawLevels(int light, int x, int y, int width, int height) const {
  const HybridMapGpu* m = map(light);
  if (!m) return;
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glViewport(x, y, width, height);
  glDisable(GL_DEPTH_TEST);
  const gl::Program& view = student.glslDescent ? levelsViewStudent_ : levelsView_;  // GLSL exercise 07.5
  view.use();
  view.set("uRoot", 0);
  view.set("uRecords", 1);
  view.set("uLevels", m->levels);
  view.set("uSize", m->sourceSize);
  const hybrid::DepthSpace space = mergeRule(light).space;
  view.set("uPerspective", space.perspective);
  view.set("uNear", space.nearZ);
  view.set("uFar", space.farZ);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, m->root.id());
  glBindSampler(0, 0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, m->records ? m->records.id() : dummy_.id());
  glBindSampler(1, 0);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glEnable(GL_DEPTH_TEST);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

void HybridShadowMaps::drawSceneView(const ShadowContext& c, HybridSceneView view, const LitSettings& lit, int light) {
  gl::Program& p = sceneView_.program(c, *this, lit);
  p.use();
  p.set("uSceneView", int(view));
  p.set("uViewLight", light);
  sceneView_.draw(c, *this, lit);
}

int HybridShadowMaps::viewLight(int preferred) const {
  if (map(preferred)) return preferred;
  for (int i = 0; i < int(lights_.size()); ++i)
    if (map(i)) return i;
  return -1;
}

}  // namespace shadowlab::tech

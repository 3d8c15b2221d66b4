#include "cascades.hpp"

#include <cstdio>
#include <string>

#include "algorithms/cascades.hpp"
#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/post_shapes.hpp"
#include "technique/map_settings.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

const glm::vec4 kCascadeColours[kMaxCascades] = {
    {1.0f, 0.35f, 0.3f, 1.0f}, {0.35f, 1.0f, 0.35f, 1.0f}, {0.35f, 0.55f, 1.0f, 1.0f}, {1.0f, 0.9f, 0.3f, 1.0f}};

// "a / b / c" of a few figures, each printed with `format`.
std::string joined(const std::vector<double>& values, const char* format, double scale) {
  std::string s;
  char b[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(b, sizeof b, format, values[i] * scale);
    s += (i ? " / " : "") + std::string(b);
  }
  return s;
}

}  // namespace

std::vector<std::string> CascadedShadowMaps::shaderDefines() const {
  std::vector<std::string> defines = maps_.shaderDefines();
  defines.push_back("SHADOW_TEXEL_JACOBIAN");  // m through each pixel's own cascade (shadow_cascades.frag)
  if (student.glslCascade) defines.push_back("SHADOWLAB_STUDENT_CASCADES");
  return defines;
}

void CascadedShadowMaps::declare(ParamRegistry& r, const std::string& n) {
  maps_.declare(r, n);
  r.add(n + "cascades", &p_.count, 1, kMaxCascades, "how many slices of the view's depth, each with its own map");
  r.add(n + "lambda", &p_.lambda, 0, 1, "the practical split scheme: 0 uniform splits, 1 logarithmic");
  r.add(n + "band", &p_.band, 0, 0.5f, "blend band: this fraction of a cascade's depth mixes into the next (0: seams)");
  r.add(n + "far", &p_.farZ, 0, 500, "where the last cascade ends (m); 0: the deepest point of the scene in view");
  r.add(n + "snap", &p_.snap, "texel snapping of each cascade's frustum (no shimmer while the camera moves)");
  r.add(n + "cull_casters", &p_.cullCasters, "draw only the casters that can shade some cascade");
  r.add(n + "cull_per_cascade", &p_.cullPerCascade,
        "each cascade draws only the casters that can reach its own light volume (off: all of them, in every one)");
  r.add(n + "colours", &p_.colours, "the cascade-colouring view: each point tinted by the cascade that shades it");
  r.add(n + "warp", &p_.warp,
        "a LiSPSM warp inside each cascade (Lloyd et al. 2006: warping plus z-partitioning); off: orthographic maps");
  r.add(n + "receivers.tiles", &p_.receiverTiles, 1, 64,
        "with the warp: rough receiver volumes, large objects cut into cells of scene size / tiles");
}

// ==== 1. the slices and their light cameras (GL-free: algorithms/cascades) ===============
shadow::CascadeSet CascadedShadowMaps::fitSet(const ShadowContext& c, const glm::vec3& direction,
                                              const shadow::CascadeViewer& viewer, const shadow::CascadeOptions& o,
                                              const std::string&) {
  return shadow::fitCascades(direction, c.scene.casterBoxes(), viewer, o);
}

bool CascadedShadowMaps::fitLight(const ShadowContext& c, int i, int side) {
  PerLight& l = lights_[std::size_t(i)];
  l.set = {};
  const Light& light = c.lights[std::size_t(i)];
  if (!light.enabled) return false;
  const std::string n = "light" + std::to_string(i) + " ";
  if (light.kind != LightKind::Directional) {
    stats_.extra.push_back({n + "cascades", "none: not a directional light (lit)"});
    return false;
  }
  shadow::CascadeOptions o;
  o.count = p_.count;
  o.lambda = p_.lambda;
  o.farZ = p_.farZ;
  o.fit.snap = p_.snap;
  o.fit.cullCasters = p_.cullCasters;
  o.fit.mapSize = side;
  o.fit.snapper = student.snap;
  o.cullPerCascade = p_.cullPerCascade;
  o.splitter = student.splits;
  const shadow::CascadeViewer viewer{c.viewer.view(), c.viewer.fovY, c.viewerAspect(), c.viewer.nearZ, c.viewer.farZ};
  l.set = fitSet(c, light.direction, viewer, o, n);
  if (!l.set.problem.empty()) {
    stats_.extra.push_back({n + "cascades", "none: " + l.set.problem + " (lit)"});
    return false;
  }
  for (const shadow::LightCamera& cam : l.set.cameras) stats_.culledCasters += cam.culled;
  std::vector<double> texels;
  for (const shadow::LightCamera& cam : l.set.cameras) texels.push_back(cam.texelWorld);
  stats_.extra.push_back({n + "splits", joined(l.set.splits, "%.3g", 1.0) + " m"});
  l.matrices.clear();
  for (const shadow::LightCamera& cam : l.set.cameras) l.matrices.push_back(glm::dmat4(cam.viewProj()));
  if (p_.warp) warpLight(c, i);
  else stats_.extra.push_back({n + "cascade texels", joined(texels, "%.3g", 100.0) + " cm"});
  return true;
}

// The warp inside each cascade: its slice's LiSPSM camera in place of the orthographic one (the
// casters stay the orthographic camera's: they are those that can shade the slice, whatever the map).
void CascadedShadowMaps::warpLight(const ShadowContext& c, int i) {
  PerLight& l = lights_[std::size_t(i)];
  const shadow::CascadeViewer viewer{c.viewer.view(), c.viewer.fovY, c.viewerAspect(), c.viewer.nearZ, c.viewer.farZ};
  const std::vector<shadow::CascadeWarp> warps = shadow::warpCascades(
      l.set, viewer, c.lights[std::size_t(i)].direction, receivers_.get(c.scene, p_.receiverTiles), p_.band);
  std::vector<double> ns;
  for (std::size_t k = 0; k < warps.size(); ++k) {
    if (warps[k].warped) l.matrices[k] = warps[k].worldToClip;
    ns.push_back(warps[k].warped ? warps[k].n : 0.0);  // 0: no receiver in the slice, orthographic
  }
  stats_.extra.push_back({"light" + std::to_string(i) + " cascade warp n", joined(ns, "%.3g", 1.0) + " m"});
}

// ==== 2. the depth passes: one layer per cascade of the light's array =========================
void CascadedShadowMaps::render(const ShadowContext& c) {
  stats_ = {};
  const int side = shadow::cascadeSide(maps_.totalSide(), p_.count);
  const glm::mat4 view = c.viewer.view();
  viewZ_ = glm::vec4(view[0][2], view[1][2], view[2][2], view[3][2]);
  near_ = c.viewer.nearZ;
  for (int i = 0; i < kPsmLights; ++i) {
    PerLight& l = lights_[std::size_t(i)];
    l.fitted = i < int(c.lights.size()) && fitLight(c, i, side);
    if (!l.fitted) {
      maps_.disable(i);
      continue;
    }
    std::vector<ProjectiveMapView> views;
    for (std::size_t k = 0; k < l.set.cameras.size(); ++k) views.push_back({l.matrices[k], l.set.cameras[k].casters});
    maps_.render(c, i, views, side, l.set.casters, psm::homogeneousLight(c.lights[std::size_t(i)]), {}, stats_);
  }
  for (std::size_t i = kPsmLights; i < c.lights.size(); ++i)
    if (c.lights[i].enabled)
      stats_.extra.push_back(
          {"light" + std::to_string(i), "no cascades (" + std::to_string(kPsmLights) + " lights at most)"});
}

// The god view: each cascade's light frustum in its colour (red, green, blue, yellow near to far).
void CascadedShadowMaps::pushShapes(const ShadowContext& c) const {
  for (const PerLight& l : lights_)
    if (l.fitted)
      for (std::size_t k = 0; k < l.matrices.size(); ++k) {
        c.debug.frustum(glm::mat4(l.matrices[k]), kCascadeColours[k]);
        c.debug.name(kCascadeColours[k], "cascade " + std::to_string(k) + "'s light box");
      }
}

// ==== 3. what the lit pass reads: the projective maps, the split distances, the band ===========
void CascadedShadowMaps::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  lit.set("uCsmViewZ", viewZ_);
  lit.set("uCsmNear", near_);
  lit.set("uCsmBand", p_.band);
  for (int i = 0; i < kPsmLights; ++i) {
    glm::vec4 far(0.0f);
    const std::vector<double>& s = lights_[std::size_t(i)].set.splits;
    for (std::size_t k = 1; k < s.size() && k <= std::size_t(kMaxCascades); ++k) far[int(k) - 1] = float(s[k]);
    lit.set(("uCsmFar[" + std::to_string(i) + "]").c_str(), far);
  }
}

void CascadedShadowMaps::renderLit(const ShadowContext& c, const LitSettings& lit) {
  auto t = gl::TimerScope(c.timers, "scene");  // the holder's lit pass is not drawn: time this one
  glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  LitSettings s = lit;
  s.depthPrepass = false;  // the colouring shader tests alpha itself
  colours_.draw(c, *this, s);
}

void CascadedShadowMaps::describePostProjective(const ShadowContext& c, int light,
                                                psm::PostProjectiveShapes& out) const {
  if (light < 0 || light >= kPsmLights || !lights_[std::size_t(light)].fitted) return;
  const PerLight& l = lights_[std::size_t(light)];
  for (std::size_t k = 0; k < l.matrices.size(); ++k)
    out.worldFrustum(postProjectiveCamera(c, light), l.matrices[k], kCascadeColours[k]);
}

}  // namespace shadowlab::tech

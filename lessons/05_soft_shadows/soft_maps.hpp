#pragma once
// The depth maps every soft-shadow technique of lesson 05 starts from: for each spherical light
// (Light::area = Sphere, radius R; without an area, R = 0 and the shadows come out hard) a
// perspective camera at the sphere's centre along the light's axis (a spot's own cone; a point
// light's cone around the scene, soft::spotCovering; a point light inside the scene, which no one
// cone can hold, a cube of six faces as lesson 03's hard point lights), and one map per face and
// sample point on the sphere, all in one GL_TEXTURE_2D_ARRAY (layer = first layer of the light +
// face x samples + sample), so a lit shader can read 64 maps of 4 lights through two texture units. A sample's camera
// is the centre camera moved by R s_k in its own view space (s_k in the unit ball), so the shader needs only the centre
// view and the samples. The depth pass is the course's one caster loop (CasterPass), each sample camera culling its own
// casters (shadow::spotCamera).
//
// GLSL: shaders/05_soft_shadows/soft_maps.glsl declares what bind() sets; a technique's visibility shader
// includes it.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/light_cameras.hpp"
#include "gl/shadow_map.hpp"
#include "technique/casters.hpp"
#include "technique/pass_key.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

struct SoftMapParams {
  int mapSize = 1024;  // texels per side of each map (kMapSizes)
  // Measured on the showcase (tools/soft_bench.sh): at 1 texel each, the normal offset alone kept
  // many point lights at 2.4 times the reference's noise; at these, 1.6 times, without acne.
  float bias = 0.5f;           // constant depth bias, in texels of world size at the receiver
  float slopeBias = 0.5f;      // times tan(theta), in texels: steep receivers need more
  float normalOffset = 0.25f;  // look up from this many texels along the normal (times sin theta)
  float offsetFactor = 1.0f;   // glPolygonOffset in the depth pass: times the caster's depth slope
  float offsetUnits = 2.0f;    // and in units of the depth format's resolution
  float minNear = 0.2f;        // the light cameras' near plane fits the scene, but not nearer than this
  // The same on two-sided materials (leaf cards, fences: thin and flat, lit from either side). The
  // slope bias moves the comparison toward the light by slope x tan(theta) texels (up to 5 at the
  // cap tan(theta) = 10), and on a card that is a contact shadow from the card it touches leaking
  // through; a step along the normal off the card's plane escapes its own depth without it. Each
  // technique picks its own (many lights: lesson 05's README, "Measured"); by default the same as
  // the solid receivers'.
  float cardSlopeBias = 0.5f;
  float cardNormalOffset = 0.25f;
  bool reuseMaps = true;  // skip the depth passes when nothing they depend on changed (PassKey)
};

// One light as the soft techniques see it this frame.
struct SoftLight {
  bool on = false;             // an enabled spot or point light with a camera around the scene
  float radius = 0;            // R (0: no spherical area)
  int faces = 1;               // 1: one frustum; 6: a cube (a point light inside the scene)
  Light spot;                  // the light as a spot (a point light's cone around the scene)
  shadow::LightCamera centre;  // from the sphere's centre (a cube: unturned; face f's is faceView)
  float tanHalfFov = 1, nearZ = 0.2f, farZ = 60;
  float casterNearZ = 0.2f;  // the nearest caster along the axis (soft::nearestCasterDepth), >= nearZ
  int firstLayer = 0;        // its faces' samples' layers in the array (face f, sample k: + f * samples + k)
  std::string why;           // when off: why (for the header)
};

// A cube face's field of view is wider than 90 degrees (tan(fov / 2) = kCubeTanHalfFov), so that a
// filter kernel, a blocker search or a sample point R away from the centre still finds its texels
// on the face its receiver falls on (the major axis picks the face): a seam needs no lookups on two
// faces. The price: at equal map size, texels 1.4 times as wide as a 90-degree face's.
constexpr float kCubeTanHalfFov = 1.4f;
// The view of face f (shadow::cubeFaceView's order +X, -X, +Y, -Y, +Z, -Z) from `position`.
glm::mat4 faceView(const glm::vec3& position, int face);

// Poisson taps as the uniform array `name` (name[0], name[1], ...).
void setTaps(const gl::Program& p, const std::string& name, const std::vector<glm::vec2>& taps);

class SoftMaps {
 public:
  explicit SoftMaps(std::string label, SoftMapParams defaults = {})
      : label_(std::move(label)), p_(defaults), casters_(label_ + ": depth pass") {}
  // reuseSwitch: declare reuse_maps (not for a technique that draws maps of its own).
  void declare(ParamRegistry& r, const std::string& prefix, bool reuseSwitch = true);
  void init();
  // Fits every light to the scene and renders one map per light and sample (samples: unit-ball
  // points in the light's view space, at most kMaxSamples). Counts into `stats`. renderMaps false:
  // only the cameras (a technique with maps of its own, VSM and ESM, uses them and the uniforms).
  // When the cameras, the casters they keep, the scene and the pass's settings are those the maps
  // were drawn with, the passes are skipped (stats.reusedMaps).
  void render(const ShadowContext& c, const std::vector<glm::vec3>& samples, ShadowStats& stats,
              bool renderMaps = true);
  // The uniforms of soft_maps.glsl, the maps with a comparison sampler on `unit` and raw (for the
  // blocker search) on unit + 1.
  void bind(const gl::Program& p, int unit) const;
  void unbind(int unit) const;
  // God view: each light's centre frustum.
  void pushShapes(const ShadowContext& c) const;

  static constexpr int kMaxSamples = 64;
  // One light's sample maps may take at most this (the course's budget, for a laptop's GPU: 64 maps
  // at 2048 are 1 GiB; 64 at 8192, 16 GiB, stopped the lesson with GL_OUT_OF_MEMORY).
  static constexpr std::uint64_t kBudgetBytes = std::uint64_t(4) << 30;
  // Registers the check that `n`samples maps of `n`map_size fit kBudgetBytes: a combination over it
  // is refused up front like any bad value (exit 2), naming the figure and what fits.
  void checkBudget(ParamRegistry& r, const std::string& n, const int* samples) const;
  const std::vector<SoftLight>& lights() const { return lights_; }
  // Face `face` of a cube light's camera from `position` (its centre, or a sample point on it),
  // casters culled to that face.
  static shadow::LightCamera faceCamera(const SoftLight& s, int face, const glm::vec3& position,
                                        const shadow::CasterBoxes& boxes);
  // A technique with maps of its own refuses a cube it cannot hold: `check(mapSize)` returns why
  // ("" where it fits), and such a light gets no soft shadow, the header saying why.
  void setCubeCheck(std::function<std::string(int)> check) { cubeCheck_ = std::move(check); }
  const std::vector<glm::vec3>& samples() const { return samples_; }
  int mapSize() const;
  const SoftMapParams& params() const { return p_; }
  SoftMapParams& params() { return p_; }

 private:
  void fit(const ShadowContext& c);
  void fitCube(const ShadowContext& c, const Light& light, SoftLight& s) const;
  void ensureArray(int size, int layers);

  std::string label_;
  SoftMapParams p_;
  CasterPass casters_;
  std::vector<SoftLight> lights_;
  std::vector<glm::vec3> samples_;
  gl::Texture array_;
  gl::Framebuffer fbo_;
  int arraySize_ = 0, arrayLayers_ = 0;
  gl::Sampler compare_, raw_;
  std::function<std::string(int)> cubeCheck_;
  PassKey rendered_;    // what the maps were last drawn from
  DrawnFigures drawn_;  // what they cost then (kept maps' figures)
};

}  // namespace shadowlab::tech

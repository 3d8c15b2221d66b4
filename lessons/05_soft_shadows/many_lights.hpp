#pragma once
// Many point lights (lesson 05): the spherical light replaced by N point lights on it, one shadow
// map each, and the N hard shadows averaged: the reference a rasteriser can reach, converging on
// the sphere's visible fraction as N grows, at N times the shadow passes and N lookups a pixel.
// The samples (algorithms/soft_shadows):
//   ball  points in the sphere whose shadow from any direction is a uniform disk
//         (isotropicBallSamples): right for every receiver
//   disk  a stratified disk across the light's axis (stratifiedDiskSamples): best along the axis,
//         foreshortened by cos(angle off the axis) toward the cone's rim
// GLSL: shaders/05_soft_shadows/shadow_many.frag (N compiled in).
#include "soft_maps.hpp"

namespace shadowlab::tech {

enum class SampleLayout { Ball, Disk };

struct ManyLightsParams {
  int samples = 16;  // N point lights per spherical light (1 is a hard shadow)
  SampleLayout layout = SampleLayout::Ball;
  // 1024^2 per sample: 64 of them hold 256 MiB (the header shows it). No slope-scaled polygon
  // offset: it scales with the CASTER's own depth slope, so a leaf card seen nearly edge-on by a
  // sample is pushed back past the card it touches and its contact shadow leaks (lesson 05's README,
  // "Measured"). The receiver's slope bias stays on solid receivers: the showcase's steep faces need
  // it. On the leaf cards none, and 0.7 texels along the normal instead (the forest's 16 lights:
  // 2.47x -> 1.99x the noise floor at R 0.6 m, 2.10x -> 1.79x at 1.2 m; the showcase unchanged).
  SoftMapParams maps{.mapSize = 1024, .offsetFactor = 0.0f, .cardSlopeBias = 0.0f, .cardNormalOffset = 0.7f};
};

class ManyLights : public ShadowTechnique {
 public:
  explicit ManyLights(ManyLightsParams defaults = {}) : p_(defaults), maps_("many lights", defaults.maps) {}
  std::string name() const override { return "many"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  void pushShapes(const ShadowContext& c) const override { maps_.pushShapes(c); }
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "05_soft_shadows/shadow_many.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override { maps_.bind(lit, firstUnit); }
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }

  ManyLightsParams& params() { return p_; }
  // The N unit samples in the light's view space for a layout (shared with the light mesh's bake).
  static std::vector<glm::vec3> samplesFor(int n, SampleLayout layout);

 private:
  void render(const ShadowContext& c) override;
  ManyLightsParams p_;
  SoftMaps maps_;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

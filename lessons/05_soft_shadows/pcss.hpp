#pragma once
// Percentage-closer filtering of one map from the sphere's centre (lesson 05), Poisson taps
// rotated per pixel, in two kinds (one class, two techniques):
//   pcf   a fixed kernel radius (texels): the baseline, one penumbra width for every caster
//   pcss  percentage-closer soft shadows (Fernando 2005): a blocker search, the penumbra estimate
//         w = (d_receiver - d_blocker) / d_blocker * R, then the filter over w: contact hardening
// Tap counts compile in (a software renderer pays for every loop trip), but for PCSS's filter:
// a uniform, so that groups of pixels with no blocker skip its loop (soft_maps.glsl). The maths:
// algorithms/soft_shadows (pcssPenumbraWidth, pcssFilterRadiusUv, pcssSearchRadiusUv, poissonDisk,
// quarterTurnDisk for the quad search).
// GLSL: shaders/05_soft_shadows/shadow_pcss.frag.
#include "soft_maps.hpp"

namespace shadowlab::tech {

struct PcssParams {
  int searchTaps = 16;       // blocker-search taps (one of kTapCounts)
  int filterTaps = 16;       // filter taps
  float fixedRadius = 3.0f;  // pcf: kernel radius in texels
  float maxSearch = 0.08f;   // pcss: cap of the search region (uv): a caster near the light is slow
  float minFilter = 1.0f;    // pcss: the smallest filter radius (texels): contacts stay antialiased
  // pcss: the four pixels of a 2x2 quad share one search, each reading a quarter of its taps (turned
  // a quarter turn from its neighbours'), the sums passed round by fine derivatives: the search's
  // reads drop to a quarter (lesson 05's README, "Measured"). Where the context has no
  // GL_ARB_derivative_control, every pixel searches alone, as with this off.
  bool quadSearch = true;
  SoftMapParams maps{.mapSize = 1024};
};

class PcssShadows : public ShadowTechnique {
 public:
  explicit PcssShadows(bool adaptive, PcssParams defaults = {});
  static inline const std::vector<int> kTapCounts{8, 16, 32, 64};  // the Poisson disks offered

  std::string name() const override { return adaptive_ ? "pcss" : "pcf"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  void pushShapes(const ShadowContext& c) const override { maps_.pushShapes(c); }
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "05_soft_shadows/shadow_pcss.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }
  PcssParams& params() { return p_; }
  // A student's version of the search (lesson 05, impl=student): shaderDefines() add
  // SHADOWLAB_STUDENT_PCSS.
  struct Student {
    bool glslSearch = false;  // 05.6: the blocker search of shaders/05_soft_shadows/exercises.glsl
  };
  Student student;

 private:
  void render(const ShadowContext& c) override;
  int searchCount() const;
  int filterCount() const;
  bool quadSearchOn() const;  // asked for, PCSS, and the context has the fine derivatives
  bool adaptive_;
  PcssParams p_;
  SoftMaps maps_;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

#pragma once
// Single-sample soft shadows (lesson 05): one map from the sphere's centre, its hard shadow kept as
// the umbra, a penumbra grown only outside it, in two kinds (one class, two techniques):
//   parker  Parker et al. 1998's outer hull around each caster, on a shadow map: the nearest
//           blocker texels around the receiver, the hull's thickness the light cone's radius at the
//           blocker (soft::outerPenumbra, soft::lightConeRadius)
//   haines  Haines 2001's plateaus on a planar receiver (the ground, y = plane): from the shadow of
//           each blocker, a plateau rising over 2r, r the lecture's d / (n.L) * R / D (soft::plateau)
// Both over-estimate the umbra (the inner penumbra is missing); the profile is A_frac or its linear
// approximation (the lecture's 7 %), a switch. GLSL: shaders/05_soft_shadows/shadow_single_sample.frag.
#include "algorithms/soft_shadows.hpp"
#include "soft_maps.hpp"

namespace shadowlab::tech {

struct SingleSampleParams {
  int searchTaps = 32;      // taps of the search (one of PcssShadows::kTapCounts)
  float maxSearch = 0.08f;  // cap of the search region (uv)
  soft::Profile profile = soft::Profile::Exact;
  float planeHeight = 0.0f;      // haines: the receiving plane y = h
  float planeTolerance = 0.02f;  // haines: how far from it a receiver still counts
  SoftMapParams maps{.mapSize = 1024};
};

class SingleSampleSoft : public ShadowTechnique {
 public:
  enum class Kind { Parker, Haines };
  explicit SingleSampleSoft(Kind kind, SingleSampleParams defaults = {});
  std::string name() const override { return kind_ == Kind::Parker ? "parker" : "haines"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  void pushShapes(const ShadowContext& c) const override { maps_.pushShapes(c); }
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "05_soft_shadows/shadow_single_sample.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }
  SingleSampleParams& params() { return p_; }

 private:
  void render(const ShadowContext& c) override;
  int searchCount() const;
  Kind kind_;
  SingleSampleParams p_;
  SoftMaps maps_;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

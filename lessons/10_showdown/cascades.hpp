#pragma once
// Cascaded shadow maps (Engel 2006; the practical split scheme of Zhang et al. 2006), the industry's
// baseline: the view's depth range cut into 1 to 4 slices, split where lambda mixes the logarithmic
// distances (ideal for perspective aliasing) with the uniform ones, each slice with its own
// orthographic map fitted to it as lesson 03 fits one map to the whole view (receivers where the
// slice meets the scene, casters that can shade them, texel snapping at the cascade's texel size).
// A blend band at each cascade's far end mixes it into the next, so the switch leaves no seam. The
// cascades of a light share its texel budget (map_size squared: four cascades of half the side).
// GL-free fit: algorithms/cascades; storage, depth pass, bias and lookup: the projective
// maps (08_psm/projective_maps, shaders/08_psm/projective_maps.glsl); the GLSL that picks the
// cascade: shaders/10_showdown/shadow_cascades.frag. view=cascades (the `colours` switch) draws the
// cascade-colouring view instead of the lit frame. warp puts a LiSPSM warp inside each cascade
// (Lloyd et al. 2006's warping plus z-partitioning: shadow::warpCascades). Directional lights only: a spot or point
// light gets no map (lit), and the header says so.
#include <vector>

#include "algorithms/cascades.hpp"
#include "technique/lit_pass.hpp"
#include "technique/post_projective_view.hpp"
#include "08_psm/projective_maps.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

inline constexpr int kMaxCascades = 4;  // uCsmFar's vec4 in shaders/10_showdown/shadow_cascades.frag

struct CascadeParams {
  ProjectiveMapParams maps;    // texels (a light's TOTAL, shared by its cascades), format, filter, bias
  int count = 4;               // cascades: 1 is lesson 03's fitted map, 4 what engines ship
  float lambda = 0.75f;        // the practical split scheme: 0 uniform, 1 logarithmic; 0.75 leans to the log
  float band = 0.1f;           // the blend band, as a fraction of a cascade's depth range (0: a hard switch)
  float farZ = 0.0f;           // > 0: the cascades end there (m); 0: at the deepest point of the scene in view
  bool snap = true;            // texel snapping per cascade: a moving camera does not make edges crawl
  bool cullCasters = true;     // draw only the casters that can shade some cascade
  bool cullPerCascade = true;  // each cascade draws only the casters that can reach its own light volume
  bool colours = false;        // the cascade-colouring view instead of the lit frame
  bool warp = false;           // a LiSPSM warp inside each cascade (Lloyd et al. 2006): off, orthographic maps
  int receiverTiles = 8;       // with the warp: the rough receiver volumes each slice's warp is fitted to
};

class CascadedShadowMaps : public ShadowTechnique, public PostProjectiveSubject {
 public:
  explicit CascadedShadowMaps(CascadeParams defaults = {}) : p_(defaults), maps_(defaults.maps) {}
  std::string name() const override { return "csm"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  void pushShapes(const ShadowContext& c) const override;  // each cascade's frustum, in its colour
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "10_showdown/shadow_cascades.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }
  // The cascade-colouring view draws the frame itself.
  bool ownsLitPass() const override { return p_.colours; }
  void renderLit(const ShadowContext& c, const LitSettings& lit) override;
  void describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const override;

  CascadeParams& params() { return p_; }
  // A student's versions of the steps (lesson 10, impl=student); empty or false: the reference.
  struct Student {
    shadow::SplitScheme splits;  // 10.1: the practical split scheme
    shadow::TexelSnapper snap;   // 10.2: texel snapping
    bool glslCascade = false;    // 10.4: cascadeAt of shaders/10_showdown/exercises.glsl (SHADOWLAB_STUDENT_CASCADES)
  };
  Student student;
  ProjectiveMapSet& maps() { return maps_; }
  // Light i's cascades this frame (empty when it has none), for tests and views.
  const shadow::CascadeSet& cascades(int light) const { return lights_[std::size_t(light)].set; }
  void drawMaps(int light, int x, int y, int w, int h) { maps_.drawLayers(light, x, y, w, h); }

 protected:
  void render(const ShadowContext& c) override;
  // Light i's slices and their light cameras: the practical split scheme over [near, the deepest
  // point of the scene in view] (algorithms/cascades). The sample-distribution cascades (sdsm.hpp)
  // split what the camera's depth buffer holds instead; `n` starts their header lines.
  virtual shadow::CascadeSet fitSet(const ShadowContext& c, const glm::vec3& direction,
                                    const shadow::CascadeViewer& viewer, const shadow::CascadeOptions& o,
                                    const std::string& n);
  ShadowStats stats_;

 private:
  struct PerLight {
    bool fitted = false;
    shadow::CascadeSet set;
    std::vector<glm::dmat4> matrices;  // each cascade's world -> map clip: its camera's, or its warp's
  };
  bool fitLight(const ShadowContext& c, int i, int side);
  void warpLight(const ShadowContext& c, int i);

  CascadeParams p_;
  ProjectiveMapSet maps_;
  std::vector<PerLight> lights_ = std::vector<PerLight>(kPsmLights);
  ReceiverVolumes receivers_;
  glm::vec4 viewZ_{0.0f};
  float near_ = 0.1f;
  LitPass colours_{"cascades: colouring view", "common/scene.vert", "10_showdown/cascade_colours.frag"};
};

}  // namespace shadowlab::tech

#pragma once
// Light Space Perspective Shadow Maps (Wimmer, Scherzer and Purgathofer 2004), the industry's answer
// to PSM and its baseline in the comparison: the perspective warp is set up in the LIGHT's space,
// along the view direction projected perpendicular to the light, so a directional light stays
// directional and one orthographic map follows; n_opt = (z0 + sqrt(z0 z1)) / sin(gamma) spreads
// the aliasing evenly over the view's depth range. GL-free fit: algorithms/psm/lispsm; it shares
// the maps, the bias controls and the GLSL (shaders/08_psm/shadow_psm.frag) with PSM. A point
// light gets a perspective map along the smallest cone from it holding the receivers (no warp:
// LiSPSM's derivation is for directional lights), or none when the light is among them.
#include <functional>
#include <vector>

#include "algorithms/psm/lispsm.hpp"
#include "technique/post_projective_view.hpp"
#include "08_psm/projective_maps.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

struct LispsmParams {
  ProjectiveMapParams maps;  // texels, format, filter, bias: the same controls as PSM
  float n = 0.0f;            // > 0 replaces n_opt (world units): large is uniform, small PSM-like
  int receiverTiles = 8;     // the rough receiver volumes the body is fitted to (as PSM's fix 2)
  bool cullCasters = true;   // draw only the casters that can shade the view frustum
};

class LightSpacePsm : public ShadowTechnique, public PostProjectiveSubject {
 public:
  explicit LightSpacePsm(LispsmParams defaults = {}) : p_(defaults), maps_(defaults.maps) {}
  std::string name() const override { return "lispsm"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  void pushShapes(const ShadowContext& c) const override;  // each fitted light's frustum
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "08_psm/shadow_psm.frag"; }
  std::vector<std::string> shaderDefines() const override { return maps_.shaderDefines(); }
  void bindVisibility(const gl::Program& lit, int firstUnit) const override { maps_.bind(lit, firstUnit); }
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }
  void describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const override;

  LispsmParams& params() { return p_; }
  ProjectiveMapSet& maps() { return maps_; }
  // A student's version of the step (lesson 09, impl=student); empty: the reference.
  struct Student {
    std::function<double(double, double, double)> optimalN;  // 09.5: n_opt (psm::lispsmOptimalN)
  };
  Student student;
  void drawMaps(int light, int x, int y, int w, int h) { maps_.drawLayers(light, x, y, w, h); }

 private:
  struct PerLight {
    bool fitted = false;
    glm::dmat4 worldToClip{1.0};
    std::vector<char> keep;
  };
  void render(const ShadowContext& c) override;
  bool fitLight(const ShadowContext& c, int i, const psm::CameraFrustum& camera);

  LispsmParams p_;
  ProjectiveMapSet maps_;
  std::vector<PerLight> lights_;
  ReceiverVolumes receivers_;
  std::vector<glm::dvec3> points_, scratch_;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

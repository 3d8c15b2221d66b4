#pragma once
// Perspective Shadow Maps: the depth map rendered and applied in the camera's post-projective
// space, where near things are big (Stamminger & Drettakis, SIGGRAPH 2002), with each fix of
// Kozlov et al., "Perspective Shadow Maps: Care and Feeding" (GPU Gems 1 ch. 14) a switch:
//   fix.inverse  §3    a light behind the camera: the inverse projection instead of the original's
//                      virtual camera slid back behind every potential caster
//   fix.clip     §4.1  the light camera fitted to the receivers' rough volumes inside the view
//                      (a coarse height map, the city's blocks, the room's walls) along the
//                      smallest cone holding them, instead of every object in the frustum
//   fix.faces    §4.2  a map on each face of the unit cube the light cannot see (3 to 5, or 6 with
//                      the light inside), chosen when the cone gets too wide, or forced
//   bias=world   §5    the world-space texel-size bias a + b L_texel, per caster vertex
//   fix.fallback       a directional light whose warp is predicted to alias more than the uniform
//                      map at the same texels gets the uniform map (psm_plan.hpp; the header says
//                      which, with the predicted ratio)
// With every switch off it is the original (lesson 08); lesson 09 turns them on one by one.
// The GL-free plan is algorithms/psm/psm_plan; the maps and their GLSL are projective_maps and
// shaders/08_psm/shadow_psm.frag. A light's texels are map_size squared however many maps it has.
#include <vector>

#include "algorithms/psm/psm_plan.hpp"
#include "technique/pass_key.hpp"
#include "technique/post_projective_view.hpp"
#include "projective_maps.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

struct PsmParams {
  ProjectiveMapParams maps;                   // texels, format, filter, bias (fix 4)
  bool inverseProjection = true;              // fix 1
  bool receiverClipping = true;               // fix 2
  psm::FaceMode faces = psm::FaceMode::Auto;  // fix 3
  bool uniformFallback = true;                // the uniform map where the warp cannot help
  float fallbackRatio = 1.0f;                 // ... predicted to alias more than this times the uniform map
  int receiverTiles = 8;                      // the rough receiver volumes: large objects in cells of scene/8
  float maxConeDegrees = 80.0f;               // faces=auto: wider cones switch to cube faces
  float nearFraction = 0.5f;                  // near plane at this share of the nearest key point
  bool cullCasters = true;                    // draw only the casters that can shade the view
  // The original PSM: every fix off, one map however wide, the constant bias.
  static PsmParams original();
};

class PerspectiveShadowMaps : public ShadowTechnique, public PostProjectiveSubject {
 public:
  explicit PerspectiveShadowMaps(PsmParams defaults = {}) : p_(defaults), maps_(defaults.maps) {}
  std::string name() const override { return "psm"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override { maps_.init(); }
  // The god view: the receivers' rough volumes, the key points, the slid virtual camera, and the
  // light frusta that are finite in world space.
  void pushShapes(const ShadowContext& c) const override;
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "08_psm/shadow_psm.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override { maps_.bind(lit, firstUnit); }
  void unbindVisibility(int firstUnit) const override { maps_.unbind(firstUnit); }
  glm::dmat4 postProjectiveCamera(const ShadowContext& c, int light) const override;
  void describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const override;

  // ---- the stages of render(), in order, for lessons 08 and 09 to call one by one ---------------
  // 1. Each light's plan (GL-free, algorithms/psm/psm_plan): the light in the camera's
  //    post-projective space, the virtual camera's slide or the inverse projection (fix 1), the
  //    receivers' key points and the smallest cone around them (fix 2) or the cube's faces (fix 3),
  //    the light camera(s); the casters that can shade the view.
  void planLights(const ShadowContext& c);
  // 2. The depth passes: one per map (or face), each caster's vertices through the plan's
  //    world -> map matrix, moved by the world-space bias (fix 4) in shaders/08_psm/depth_psm.vert.
  void renderDepth(const ShadowContext& c);

  PsmParams& params() { return p_; }
  // This frame's plan of light i (nullptr for a light without one), and its key points.
  const psm::PsmPlan* plan(int light) const;
  std::span<const glm::dvec3> worldKeyPoints(int light) const;
  // A student's versions of the steps (lessons 08 and 09, impl=student); empty or false: the reference.
  struct Student {
    std::function<psm::PostProjectiveLight(const glm::dmat4&, const glm::dvec4&)> toPostProjective;  // 08.1
    std::function<double(const psm::CameraFrustum&, std::span<const Aabb>)> virtualShift;            // 08.2
    psm::PsmSteps fixes;                    // 09.1 the inverse projection, 09.2 the smallest cone, 09.3 the face test
    ProjectiveMapSet::WorldBias worldBias;  // 09.4: the casters moved per vertex on the CPU (lesson 09)
    bool glslLookup = false;                // 08.3: the lookup in the map (shaders/08_psm/exercises.glsl)
    bool glslFaces = false;                 // 09.6: the face map of a point (shaders/09_psm_fixes/exercises.glsl)
  };
  Student student;
  ProjectiveMapSet& maps() { return maps_; }
  // Draws light i's maps side by side (view=map).
  void drawMaps(int light, int x, int y, int w, int h) { maps_.drawLayers(light, x, y, w, h); }

 private:
  struct PerLight {
    psm::PsmPlanner planner;
    bool planned = false;
    std::vector<char> keep;
    std::vector<Aabb> casterBoxes;
  };
  void render(const ShadowContext& c) override;
  psm::PsmSwitches switches() const;
  void planLight(const ShadowContext& c, int i, const psm::CameraFrustum& camera);
  void renderLight(const ShadowContext& c, int i);
  void addCounters(int i);

  PsmParams p_;
  ProjectiveMapSet maps_;
  std::vector<PerLight> lights_;
  ReceiverVolumes receiverCache_;
  std::span<const Aabb> receivers_;
  std::vector<psm::SurfaceSample> seen_;  // the surfaces the camera sees: the fall-back's prediction
  PassKey seenKey_;                       // the scene and camera they were cast for
  ShadowStats stats_;
};

// The viewer as the PSM maths sees it (double precision, GL projection).
psm::CameraFrustum viewerFrustum(const ShadowContext& c);

}  // namespace shadowlab::tech

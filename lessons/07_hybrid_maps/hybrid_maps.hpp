#pragma once
// The hybrid-resolution shadow-map technique (lesson 07; Li, Yang, Zhao, Chen, "Hybrid-resolution
// shadow mapping design and hard shadows anti-aliasing in special effects movies", Chinese Optics
// 9(1), 2016). Per directional or spot light:
//   1. the light camera      as the uniform maps fit theirs (algorithms/light_cameras: fitMap2D)
//   2. the depth pass        the full-resolution map (N x N, 16/24/32F bits), CasterPass
//   3. the merge sweep       bottom-up over 2x2 blocks, 1 to 3 levels (HybridBuilder, GPU passes)
//   4. the index             the root grid and the records of the texels that did not merge
//   5. the lookup            shaders/07_hybrid_maps/shadow_hybrid.frag: root texel, down the index, compare
// The sweep and the index can run on the CPU instead (build=cpu: read back, swept by
// algorithms/hybrid_map, uploaded): the reference the GPU is tested against, and where a student's
// sweep runs (impl=student in lesson 07). Point lights have no hybrid map (the paper's maps are 2D):
// they are left unshadowed and the header says so.
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "algorithms/hybrid_map.hpp"
#include "algorithms/light_cameras.hpp"
#include "gl/shadow_map.hpp"
#include "technique/casters.hpp"
#include "hybrid_build.hpp"
#include "technique/lit_pass.hpp"
#include "technique/map_settings.hpp"
#include "technique/pass_key.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

enum class HybridFilter { Nearest, Bilinear2x2, BoxNxN };
enum class HybridPath { Gpu, Cpu };
// What drawSceneView shows on the scene: the level each pixel's lookup reached, or its steps.
enum class HybridSceneView { Levels, Steps };

// Bias, fit, culling and the spot's range come from MapSettings (the uniform maps' names).
struct HybridMapParams : MapSettings {
  int mapSize = 2048;                                       // N, the full map the sweep starts from: any size, so a
                                                            // standard map (levels 0) can match another's memory
  gl::DepthFormat format = gl::DepthFormat::Depth16;        // of the full map: 16 bits, as the paper
  int levels = 2;                                           // sweeps: the paper's two, 2048 -> 1024 -> 512
  hybrid::Criterion criterion = hybrid::Criterion::Window;  // the paper's: window depth
  float eps0 = 0.25f;                                       // the paper's threshold (window and linear depth)
  float maxSlope = 2.0f;                                    // the slope criterion's |dz/dx| + |dz/dy|
  HybridPath build = HybridPath::Gpu;                       // the sweep on the GPU, or on the CPU (the reference)
  HybridFilter filter = HybridFilter::Nearest;              // the paper's single comparison
  int pcfSize = 3;                                          // N of N x N PCF (each tap descends)
  bool reuseMaps = true;  // skip a light's depth pass, sweep and index when nothing they depend on changed
};

class HybridShadowMaps : public ShadowTechnique {
 public:
  explicit HybridShadowMaps(HybridMapParams defaults = {});
  ~HybridShadowMaps() override;

  std::string name() const override { return "hybrid"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;
  // The god view's shapes: each mapped light's frustum, and the bounds the directional fit clips against.
  void pushShapes(const ShadowContext& c) const override;
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "07_hybrid_maps/shadow_hybrid.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override;
  // A student's versions of the steps (lesson 07, impl=student); empty or false: the reference.
  struct Student {
    // 07.2: one level of the sweep; when set, the maps are built on the CPU with it
    std::function<hybrid::MergeGrid(const hybrid::MergeGrid&, const hybrid::MergeRule&, int)> sweep;
    bool glslDescent = false;  // 07.5: the index descent of shaders/07_hybrid_maps/exercises.glsl
  };
  Student student;

  // ---- the stages of render(), in order, for lesson 07 to call one by one ----------------------
  void fitLights(const ShadowContext& c);    // 1. light cameras (GL-free)
  void renderDepth(const ShadowContext& c);  // 2. the full-resolution depth maps
  void buildMaps(const ShadowContext& c);    // 3.-4. the merge sweep and the index, GPU or CPU; the figures

  // ---- views ------------------------------------------------------------------------------------
  // Light `light`'s map over the light's view, each source texel coloured by the level it is stored
  // at (0 red, 1 yellow, 2 green, 3 blue), darker for nearer depth; into a viewport of the bound
  // framebuffer. Nothing when the light has no map.
  void drawLevels(int light, int x, int y, int width, int height) const;
  // The scene, each pixel coloured by the level its lookup of light `light` reached, or by the
  // steps it took (0 blue .. 3 red), shaded by V: drawn instead of the lit pass.
  void drawSceneView(const ShadowContext& c, HybridSceneView view, const LitSettings& lit, int light);
  // The light the views show: `preferred` when it has a map, else the first light that has one (-1: none).
  int viewLight(int preferred) const;

  // ---- hooks and access ---------------------------------------------------------------------------
  HybridMapParams& params() { return p_; }
  const HybridMapParams& params() const { return p_; }
  // Light i's map and camera this frame (nullptr when it has none).
  const HybridMapGpu* map(int light) const;
  const gl::ShadowMap* depthMap(int light) const;
  const shadow::Map2DCamera* camera(int light) const;
  // The rule light i's sweep uses (its depth space from its camera).
  hybrid::MergeRule mergeRule(int light) const;

 private:
  struct PerLight {
    bool on = false;      // a directional or spot light that is enabled
    bool point = false;   // an enabled point light: no hybrid map
    gl::ShadowMap depth;  // the full-resolution map
    shadow::Map2DCamera camera;
    HybridMapGpu map;
    PassKey rendered;     // what the map was last built from (PassKey)
    DrawnFigures drawn;   // what its depth pass cost then (a kept map's figures)
    bool reused = false;  // this frame: nothing changed, the map from an earlier frame stays
  };
  void render(const ShadowContext& c) override;
  PassKey passKey(const ShadowContext& c, const PerLight& l) const;
  void buildOnCpu(PerLight& l, const hybrid::MergeRule& rule);
  void bindLight(const gl::Program& p, int i, int unitRoot, int unitRecords) const;
  void pushStats(int i, const PerLight& l);

  HybridMapParams p_;
  std::vector<std::unique_ptr<PerLight>> lights_;
  CasterPass casters_{"hybrid maps: depth pass"};
  HybridBuilder builder_{"hybrid maps"};
  gl::Texture dummy_;  // an RGBA32UI texel bound where a light has no map
  gl::Program levelsView_{"hybrid maps: levels view", {"common/fullscreen.vert", "07_hybrid_maps/levels_view.frag"}};
  // The same view through the student's descent (student.glslDescent): required only while it is in use.
  gl::Program levelsViewStudent_{"hybrid maps: levels view (student GLSL)",
                                 {"common/fullscreen.vert", "07_hybrid_maps/levels_view.frag"},
                                 {"SHADOWLAB_STUDENT_DESCENT"}};
  gl::VertexArray vao_;
  LitPass sceneView_{"hybrid maps: scene view", "common/scene.vert", "07_hybrid_maps/scene_view.frag"};
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

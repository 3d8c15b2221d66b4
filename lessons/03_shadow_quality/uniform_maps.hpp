#pragma once
// The uniform shadow-map technique (lesson 03, Williams 1978 with everything that makes it good):
// one depth map per light, uniform texels in the light's own space,
//   directional  an orthographic map fitted to the receivers in view (or the whole scene), casters
//                culled against the light volume swept from the view frustum, texel snapping
//   spot         a perspective map around the cone, casters culled against its frustum
//   point        a cube map, casters culled per face, faces the view cannot see skipped
// with the bias family (constant, slope-scaled in the shader and by polygon offset, normal offset,
// receiver plane, front-face culling) and the PCF family (nearest, hardware 2x2, N x N, Poisson).
// The light cameras are GL-free (algorithms/light_cameras); the GLSL is
// shaders/03_shadow_quality/shadow_uniform.frag.
#include <array>
#include <vector>

#include "algorithms/light_cameras.hpp"
#include "gl/shadow_map.hpp"
#include "technique/casters.hpp"
#include "technique/pass_key.hpp"
#include "technique/post_projective_view.hpp"
#include "technique/map_settings.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

enum class Filter { Nearest, Hardware2x2, BoxNxN, Poisson };

// Bias, fit, culling and the spot's range come from MapSettings (shared with the hybrid maps).
struct UniformMapParams : MapSettings {
  int mapSize = 2048;                                 // texels per side (directional, spot), one of kMapSizes
  int cubeSize = 1024;                                // texels per side of a cube face
  gl::DepthFormat format = gl::DepthFormat::Depth24;  // every map's depth format
  Filter filter = Filter::Hardware2x2;                // GL_LINEAR on a comparison sampler: free 2x2 PCF
  int pcfSize = 3;                                    // N of N x N PCF (odd)
  float poissonRadius = 2.0f;                         // Poisson disk radius in texels
  bool receiverPlane = false;                         // filter taps compare against the receiver's plane
  bool skipFaces = true;                              // skip cube faces whose frustum misses the view frustum
  float cubeNear = 0.2f, cubeFar = 60.0f;             // the cube faces' depth range
  bool reuseMaps = true;                              // skip a map's pass when nothing it depends on changed
};

class UniformShadowMaps : public ShadowTechnique, public PostProjectiveSubject {
 public:
  explicit UniformShadowMaps(UniformMapParams defaults = {}) : p_(defaults) {}

  std::string name() const override { return "uniform"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;
  // The god view's shapes: each light's frustum (directional, spot) or position (point), and the
  // scene's bounds the directional fit clips against.
  void pushShapes(const ShadowContext& c) const override;
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "03_shadow_quality/shadow_uniform.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override;
  // Light i's frustum (2D maps) in the post-projective view: what a uniform map spends its texels on.
  void describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const override;

  // ---- the stages of render(), in order, for lesson 03 to call one by one ----------------------
  // 1. Each light's camera, fitted to the view, its casters culled, a point light's faces skipped
  //    (GL-free: algorithms/light_cameras); its map made the right size.
  void fitLights(const ShadowContext& c);
  // 2. The depth passes: polygon offset, one pass per 2D map and per cube face not skipped; a map
  //    nothing invalidated is kept.
  void renderDepth(const ShadowContext& c);

  // A student's versions of the steps (lesson 03, impl=student); empty or false: the reference.
  struct Student {
    shadow::CasterTest casterTest;  // 03.4: may a caster shade the view?
    shadow::OrthoFitter fitter;     // 03.5: the sun's orthographic fit
    bool glslPcf = false;           // 03.6: the N x N kernel of shaders/03_shadow_quality/exercises.glsl
  };
  Student student;

  UniformMapParams& params() { return p_; }
  // Light i's 2D map (directional or spot, when on), for views of the map; nullptr otherwise.
  const gl::ShadowMap* map2D(int light) const;
  // Light i's camera this frame (2D maps), for the god view and for tests.
  const shadow::LightCamera* camera(int light) const;

 private:
  enum class Type { None, Ortho, Perspective, Cube };
  struct PerLight {
    Type type = Type::None;
    gl::ShadowMap map;
    shadow::LightCamera camera;                // 2D maps
    std::array<shadow::LightCamera, 6> faces;  // cube map
    glm::mat4 textureMatrix{1.0f};
    float texel = 0.0f;  // ortho: world texel; perspective: 2 tan(fov / 2) / size
    PassKey rendered;    // what the map holds now (empty: nothing valid)
    DrawnFigures drawn;  // what it cost when drawn (a kept map's figures)
  };
  PassKey passKey(const ShadowContext& c, const PerLight& l) const;
  void render(const ShadowContext& c) override;
  void fitLight(const ShadowContext& c, int i, const shadow::ConvexVolume& view);
  void renderLight(const ShadowContext& c, int i);
  void countMemory();

  UniformMapParams p_;
  std::vector<PerLight> lights_;
  CasterPass casters_{"uniform maps: depth pass"};
  gl::Sampler compareNearest_, compareLinear_;
  gl::ShadowMap dummy2D_, dummyCube_;  // bound where a light has no map of that kind
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

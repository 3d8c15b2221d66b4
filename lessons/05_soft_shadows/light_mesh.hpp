#pragma once
// The light-mesh method of the lecture (lesson 05): the light's visibility sampled on a regular 3D
// grid over the scene, each shaded point averaging its nearest nodes (here the 8 around it,
// trilinear: soft::makeLightGrid, soft::lightMeshVisibility). The nodes are baked on the GPU from
// many point lights on the sphere (ManyLights' samples and SoftMaps), one z-slice at a time into a
// 3D texture, and only again when the scene, a light or the grid changed: a static scene pays the
// bake once, then one texture lookup a pixel. What it costs and cannot do, in the header: the
// memory of the grid, the build time, and shadows no finer than a cell.
// GLSL: shaders/05_soft_shadows/light_mesh_bake.frag (the bake), shadow_light_mesh.frag (the lookup).
#include <array>

#include "algorithms/soft_shadows.hpp"
#include "many_lights.hpp"

namespace shadowlab::tech {

struct LightMeshParams {
  int nodes = 48;                      // grid nodes along the scene's longest side (the others at the same spacing)
  int samples = 16;                    // point lights on the sphere for the bake
  float offset = 0.5f;                 // the lookup moves this many cells along the normal (out of the receiver)
  SoftMapParams maps{.mapSize = 512};  // per sample map
};

class LightMesh : public ShadowTechnique {
 public:
  explicit LightMesh(LightMeshParams defaults = {}) : p_(defaults), maps_("light mesh", defaults.maps) {}
  std::string name() const override { return "mesh"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "05_soft_shadows/shadow_light_mesh.frag"; }
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override;
  LightMeshParams& params() { return p_; }
  const soft::LightGrid& grid() const { return grid_; }
  double lastBuildMs() const { return buildMs_; }

  // No shapes for the god view: the grid is the scene's, not the viewer's.

 private:
  void render(const ShadowContext& c) override;
  std::string key(const ShadowContext& c) const;
  void bake(const ShadowContext& c);
  void countStats();

  LightMeshParams p_;
  SoftMaps maps_;
  soft::LightGrid grid_;
  std::array<gl::Texture, kMaxLights> meshes_;  // per light, R8
  std::array<bool, kMaxLights> on_{};
  gl::Texture dummy_;  // 1^3, visibility 1: bound where a light has no mesh
  gl::Framebuffer fbo_;
  gl::VertexArray vao_;
  gl::ProgramVariants bakePrograms_{"light mesh bake",
                                    {"common/fullscreen.vert", "05_soft_shadows/light_mesh_bake.frag"}};
  std::string key_;
  double buildMs_ = 0;
  int builds_ = 0;
  ShadowStats stats_, bakeStats_;
};

}  // namespace shadowlab::tech

#pragma once
// Stencil shadow volumes (lesson 04; the lecture's passes made robust after Everitt and Kilgard,
// "Practical and Robust Stenciled Shadow Volumes", 2002), a technique that owns its lit pass:
//   1. depth and ambient   the scene once: depth, ka Ia, and V = 0 for the measurement
//   per light (scissored to its reach):
//   2. stencil counting    the volumes: silhouette quads to infinity (w = 0), caps for z-fail;
//                          z-pass or z-fail per object (z-fail only where its volume can reach the
//                          viewer's near plane); two-sided stencil in one pass, or two passes
//   3. lit pass            the scene again, adding the light where the count is 0
//   4. views               the volumes, their wireframe, the stencil count as a heatmap, silhouettes
// Silhouettes come from an edge adjacency built once per mesh, on the CPU (cached per light) or in
// a geometry shader (triangles_adjacency). An infinite far plane (or GL_DEPTH_CLAMP) keeps the far
// caps unclipped. Open meshes are found when the adjacency is built: skipped, or z-pass only.
// The maths is GL-free in algorithms/shadow_volume; the shaders are in shaders/04_shadow_volumes/.
#include <functional>
#include <optional>
#include <vector>

#include "algorithms/shadow_volume.hpp"
#include "app/exercise_program.hpp"
#include "technique/pass_key.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

struct StencilVolumeParams {
  enum class View { Lit, Volumes, Wireframe, Stencil, Silhouettes };
  enum class Method { Auto, ZPass, ZFail };
  enum class Silhouettes { Cpu, Gpu };
  enum class FarPlane { Infinite, DepthClamp };
  enum class OpenMeshes { Skip, ZPassOnly };
  View view = View::Lit;                       // the inner buffers: volumes, stencil counts, silhouettes
  int viewLight = 0;                           // whose volumes / stencil the views show
  Method method = Method::Auto;                // auto: z-fail only where z-pass can fail
  Silhouettes silhouettes = Silhouettes::Cpu;  // CPU (cached per light) or geometry shader (every frame)
  bool twoSided = true;                        // glStencilOpSeparate: both faces in one pass
  FarPlane far = FarPlane::Infinite;           // how the points at infinity escape the far clip plane
  OpenMeshes openMeshes = OpenMeshes::Skip;    // an open mesh's volume has holes: skip or z-pass only
  bool scissor = true;                         // each light touches only the pixels within its reach
  bool fillQuery = true;                       // count every volume fragment (occlusion query)
};

class StencilVolumes : public ShadowTechnique {
 public:
  explicit StencilVolumes(StencilVolumeParams defaults = {}) : p_(defaults) {}
  std::string name() const override { return "volumes"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;
  const ShadowStats& stats() const override { return stats_; }
  bool ownsLitPass() const override { return true; }
  // The lit frame: beginFrame, depthAndAmbient, renderLight for every light, finishFrame.
  void renderLit(const ShadowContext& c, const LitSettings& lit) override;

  // ---- the stages of renderLit(), in order, for lesson 04 to call one by one -------------------
  // What one frame's passes share: the camera drawn with (far plane at infinity, or finite with
  // depth clamping), the viewer's near rectangle (z-pass or z-fail is decided for the viewer, also
  // when the god view draws), and per light which casters go z-fail.
  struct Frame {
    const ShadowContext& c;
    glm::mat4 viewProj{1.0f};
    volume::NearRect nearRect;
    std::vector<int> zFail;
  };
  Frame beginFrame(const ShadowContext& c);
  // 1. The scene once: its depth for every light's counting, ka Ia, and V = 0 for the measurement.
  void depthAndAmbient(const Frame& f, const LitSettings& lit);
  // 2.-3. Light i, scissored to its reach: the stencil count of its volumes (z-pass or z-fail per
  // caster), then the light added where the count is 0.
  void renderLight(const Frame& f, int light, const LitSettings& lit);
  // 4. The views (volumes, wireframe, silhouettes), the god view's lines, the header's figures.
  void finishFrame(const Frame& f);

  // A student's versions of the steps (lesson 04, impl=student); empty or false: the reference.
  struct Student {
    std::function<volume::StencilOps(bool zFail)> stencilOps;                                            // 04.3
    volume::SilhouetteTest isSilhouette = nullptr;                                                       // 04.1
    std::function<glm::mat4(float fovY, float aspect, float nearZ, float epsilon)> infinitePerspective;  // 04.2
    std::function<bool(const Aabb&, const volume::NearRect&, const glm::vec4&)> mayReachNearPlane;       // 04.4
    // 04.5: the extrusion to infinity of shaders/04_shadow_volumes/exercises.glsl in the geometry
    // shader (silhouettes=gpu)
    bool glslExtrusion = false;
  };
  Student student;
  StencilVolumeParams& params() { return p_; }
  // The stencil view's colour key (none in the other views).
  std::optional<Legend> legend() const;

 private:
  // One light's volumes for every caster, built on the CPU and kept on the GPU until the light,
  // the scene or the implementation changes.
  struct VolumeCache : volume::SceneVolumes {
    glm::vec4 light{0.0f};
    std::uint64_t key = 0;
    gl::Buffer buffer;
    gl::VertexArray vao;
  };
  struct AdjacencyMesh {
    gl::VertexArray vao;
    gl::Buffer vertices, indices;
    GLsizei count = 0;
  };
  struct Fill {
    gl::Query query;
    bool issued = false;
    GLuint samples = 0;
    PassKey counted;  // what the last query counted: the same volumes in the same view count the same
  };
  // Builds the edge adjacency (once per mesh) and finds the casters with a closed volume; the
  // passes need the frame's depth, so they all run in renderLit.
  void render(const ShadowContext& c) override;

  bool casts(std::size_t object) const;
  // What this context runs of the parameters: WebGL2 has no geometry shader (silhouettes on the
  // CPU), may lack EXT_depth_clamp (the infinite far plane) and WEBGL_polygon_mode (the wireframe filled).
  bool gpuSilhouettes() const;
  bool depthClamp() const;
  void buildAdjacency(const SceneCache& scene);
  void buildVolumes(const ShadowContext& c, VolumeCache& cache, const glm::vec4& light);
  void countStencil(const Frame& f, int light, const VolumeCache& cache, const glm::vec4& L);
  void litPass(const Frame& f, int light, const LitSettings& lit);
  void drawVolumes(const Frame& f, const VolumeCache& c, const glm::vec4& L, bool zFail);
  void measureFill(const Frame& f, int light, const VolumeCache& c, const glm::vec4& L);
  void drawStencilHeatmap();
  void drawVolumesView(const VolumeCache& c, const glm::mat4& viewProj);
  void drawSilhouettes(const VolumeCache& c, const glm::mat4& viewProj);
  void pushGodViewShapes(const ShadowContext& c, const VolumeCache& shown) const;
  void drawScene(const Frame& f, const gl::Program& program, const LitSettings& lit);

  StencilVolumeParams p_;
  std::vector<volume::EdgeAdjacency> adjacency_;
  std::vector<AdjacencyMesh> adjacencyGpu_;
  std::uint64_t adjacencyRevision_ = 0;
  std::vector<VolumeCache> caches_;
  std::vector<Fill> fill_;
  std::vector<char> casting_;  // per object: 1 when it casts a volume (closed, or open and drawn z-pass)
  int zPassCount_ = 0, zFailCount_ = 0;
  std::size_t volumeTriangles_ = 0;  // volume triangles drawn this frame (counting and fill passes)
  gl::Program ambient_{"volumes: depth + ambient", {"common/scene.vert", "04_shadow_volumes/ambient.frag"}};
  gl::ProgramVariants lit_{"volumes: lit", {"common/scene.vert", "04_shadow_volumes/lit.frag"}};  // per light kind
  gl::Program volume_{"volumes: volume", {"04_shadow_volumes/volume.vert", "04_shadow_volumes/volume.frag"}};
  ExerciseProgram volumeGs_{
      "volumes: volume gs",
      {"04_shadow_volumes/volume_gs.vert", "04_shadow_volumes/volume.geom", "04_shadow_volumes/volume.frag"},
      [this] { return student.glslExtrusion; }};
  gl::Program heat_{"volumes: stencil heatmap", {"common/fullscreen.vert", "04_shadow_volumes/heat.frag"}};
  gl::VertexArray emptyVao_, lineVao_;
  gl::Buffer lineBuffer_;
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

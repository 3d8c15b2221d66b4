#pragma once
// The technique layer: every shadow technique of the course as a module that a lesson, the A/B
// split and the showdown can hold, several at once. Each lives in the lesson that teaches it
// (lessons/03_shadow_quality/uniform_maps, lessons/04_shadow_volumes/stencil_volumes, ...). A
// technique
//   declare(r, prefix)    registers its parameters under a prefix ("" keeps the bare names, for the
//                         lesson whose subject it is; the showdown gives each its own prefix)
//   init()                creates its GL resources (programs, samplers)
//   renderShadows(c)      this frame's shadow passes: render(c), its stages in order (fit itself
//                         to the viewer, the scene and the lights, then draw its maps under timer
//                         scopes), then pushShapes(c) for the god view. The lesson that teaches a
//                         technique calls the stages itself, under its own numbered banners.
//   then, for the lit pass, one of two ways:
//     map techniques      name a fragment shader defining the one GLSL function every lit shader
//                         calls (see shaders/common/scene.frag),
//                           float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texel);
//                         and bind what it reads (bindVisibility); LitPass links the two
//     lit-pass owners     (stencil volumes) draw the lit frame themselves: renderLit(c, lit)
//   stats()               shadow triangles, texels, bytes, culled casters, skipped faces, reused maps
// docs/adding_a_technique.md walks through writing one.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/lesson.hpp"
#include "core/light.hpp"
#include "core/params.hpp"
#include "gl/program.hpp"

namespace shadowlab::tech {

class SceneCache;

// What a technique sees of the frame being drawn.
struct ShadowContext {
  const FrameInfo& frame;         // where and from which camera to draw (the god view's, sometimes)
  const OrbitCamera& viewer;      // the camera the shadows serve: fit to this, never to frame.view
  const SceneCache& scene;        // everything that casts and receives
  std::span<const Light> lights;  // the lesson's lights, in its own order (light i is uLights[i])
  gl::GpuTimers& timers;          // one scope per pass
  DebugDraw& debug;               // shapes for the god view
  float viewerAspect() const { return float(frame.width) / float(frame.height > 0 ? frame.height : 1); }
  glm::mat4 viewerViewProj() const { return viewer.projection(viewerAspect()) * viewer.view(); }
};

// What the lit pass needs that is not the technique's: the lecture's model's other terms.
struct LitSettings {
  glm::vec3 ambient{0.1f};         // ka Ia
  int view = 0;                    // 0 lit, 1 the visibility of the measured light (white lit, black shadowed)
  std::optional<float> specular;   // override every material's ks (a lesson's slider)
  std::optional<float> shininess;  // override every material's exponent
  // Lay down the depth first with a trivial shader, then shade each pixel once (depth EQUAL): the
  // lit shader's cost is paid per pixel, not per overlapping fragment, and needs no alpha discard.
  bool depthPrepass = true;
};

// What a map cost when it was drawn: a map kept from an earlier frame reports these, marked kept
// (a still camera must not make a shadow lesson's header read "shadow triangles: 0").
struct DrawnFigures {
  std::size_t triangles = 0;
  std::uint64_t texels = 0;
};

// "12000", "12000 (kept, as drawn)" or "20000 (12000 of them kept)": a figure of the maps drawn
// now and of those kept, as the header and the benchmarks read it (its number first).
std::string drawnFigure(std::uint64_t now, std::uint64_t kept);

// The work a technique spent and skipped in its last frame, for the header and the benchmarks.
struct ShadowStats {
  std::size_t triangles = 0;   // triangles drawn into shadow maps or volumes
  std::uint64_t texels = 0;    // shadow-map texels rendered this frame
  std::uint64_t bytes = 0;     // GPU memory the technique holds (maps, volumes, indices)
  int culledCasters = 0;       // casters left out of a light camera (counted per camera)
  int skippedFaces = 0;        // cube faces not rendered
  int reusedMaps = 0;          // maps kept from an earlier frame because nothing changed
  DrawnFigures kept;           // what those kept maps cost when they were drawn
  bool culls = true;           // the technique culls casters and skips faces (else those lines are left out)
  std::vector<Counter> extra;  // the technique's own figures ("light0 texel", "z-fail objects")
  // The header lines: the shared figures first, under the names the benchmark runner reads.
  std::vector<Counter> counters() const;

  // `maps` maps kept from an earlier frame, which cost `drawn` when they were drawn.
  void keep(const DrawnFigures& drawn, int maps = 1) {
    reusedMaps += maps;
    kept.triangles += drawn.triangles;
    kept.texels += drawn.texels;
  }
  // Writes into `out`, at the end of its scope, what was drawn since it was made: a map's cost,
  // kept beside the map for the frames that keep it.
  class Recorder {
   public:
    Recorder(const ShadowStats& s, DrawnFigures& out) : stats_(s), out_(out), before_{s.triangles, s.texels} {}
    ~Recorder() { out_ = {stats_.triangles - before_.triangles, stats_.texels - before_.texels}; }
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

   private:
    const ShadowStats& stats_;
    DrawnFigures& out_;
    DrawnFigures before_;
  };
};

class ShadowTechnique {
 public:
  virtual ~ShadowTechnique() = default;
  virtual std::string name() const = 0;  // the choice's name: "uniform", "volumes"
  virtual void declare(ParamRegistry& r, const std::string& prefix) = 0;
  virtual void init() = 0;
  // This frame's shadow passes for the viewer (render), then the god view's shapes. The god view
  // draws the viewer's frame again from outside (frame.godView): the maps that frame made stay, and
  // only the shapes are pushed again.
  void renderShadows(const ShadowContext& c) {
    if (!c.frame.godView) render(c);
    pushShapes(c);
  }
  // The shapes the god view draws: the light frusta, cones and volumes of this frame's passes.
  virtual void pushShapes(const ShadowContext& c) const {}
  virtual const ShadowStats& stats() const = 0;

  // ---- map techniques: the lesson's lit shader calls shadowVisibility() -----------------------
  // The fragment shader (relative to shaders/) defining shadowVisibility, linked into lit programs.
  virtual std::string visibilityShader() const { return ""; }
  // #defines that specialise the lit program for the technique's current settings.
  virtual std::vector<std::string> shaderDefines() const { return {}; }
  // Uniforms and textures for the bound lit program; units from `firstUnit` up are the technique's.
  virtual void bindVisibility(const gl::Program& lit, int firstUnit) const {}
  virtual void unbindVisibility(int firstUnit) const {}

  // ---- techniques that own the lit pass (stencil volumes) ---------------------------------------
  virtual bool ownsLitPass() const { return false; }
  virtual void renderLit(const ShadowContext& c, const LitSettings& lit) {}

 protected:
  // The passes for the viewer's frame, in order: fit, cull, render (never for the god view's).
  virtual void render(const ShadowContext& c) = 0;
};

}  // namespace shadowlab::tech

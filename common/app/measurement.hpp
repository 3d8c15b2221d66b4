#pragma once
// Measuring a lesson's shadows against ground truth, for any lesson that describes its scene and
// lights (Lesson::measureSource). The lesson's scene shader writes, through
// shaders/common/measure.glsl, the world position and normal of every pixel it shades, its own
// visibility V of the measured light, and the shadow-texel Jacobian. The framework renders the
// frame into a target with those attachments, reads them back, casts Embree rays from exactly
// those points (common/measure), and shows the result:
//   overlay=error     light leaks (red) and false shadows (blue) over the frame
//   overlay=aliasing  m = 1 / sigma_min(J): screen pixels per shadow texel (m <= 1 alias-free)
//   overlay=reference the ground-truth visibility itself
// Interactive by construction: recomputed only when the view or a parameter changed, at a reduced
// resolution (measure.scale), with its cost in the header.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_info.hpp"
#include "gl/attachments.hpp"
#include "core/image.hpp"
#include "core/light.hpp"
#include "core/params.hpp"
#include "core/scene.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"
#include "measure/ground_truth.hpp"
#include "measure/metrics.hpp"

namespace shadowlab {

// A heatmap's colour key: the header of every view that colours a quantity draws one (error,
// aliasing m, stencil counts, mip levels), so a projected picture can be read from the back row.
struct Legend {
  struct Entry {
    glm::vec3 color;  // linear 0..1, as drawn
    std::string label;
  };
  std::string title;
  std::vector<Entry> entries;
};

// Draws what is not a measured surface (overlays, lines, translucent volumes) into a measured frame
// without touching the measurement attachments 1-3, so the surfaces under it stay measured: the
// alternative to writeNoMeasurement() in the shader, for overlays that must not erase what is below.
template <class Draw>
void withoutMeasurement(Draw&& draw) {
  for (GLuint a = 1; a <= 3; ++a) gl::colorMaskAttachment(a, false);
  draw();
  for (GLuint a = 1; a <= 3; ++a) gl::colorMaskAttachment(a, true);
}

// What a lesson hands the framework so it can be measured.
struct MeasureSource {
  const Scene* scene = nullptr;     // everything that casts shadows, on the CPU
  std::uint64_t sceneRevision = 0;  // change it when the scene changes: the BVH is rebuilt then only
  std::vector<Light> lights;        // the lesson's lights, in its own order
  // Also measure the pixels near shadow edges (MeasureResult::band): facing pixels within this
  // distance of a reference shadow boundary, across the light (measure::shadowEdgeBand): world
  // units for a directional light, a width at unit distance for a spot or point light. 0: not.
  float edgeBand = 0.0f;
  // Why this frame's picture cannot be measured against one ground truth, "" when it can (lesson
  // 10's four-up view shows four techniques): no figures and no overlay then, this note instead.
  std::string unmeasurable;
};

struct MeasureResult {
  bool valid = false;
  std::string unmeasurable;  // the lesson's reason when it was not measured (MeasureSource::unmeasurable)
  bool soft = false;
  measure::HardShadowErrors hard;
  measure::SoftShadowErrors soft_;
  bool hasAliasing = false;
  measure::AliasingStats aliasing;
  bool hasBand = false;  // the figures of the pixels near shadow edges (MeasureSource::edgeBand)
  float bandRadius = 0.0f;
  measure::HardShadowErrors band;
  measure::AliasingStats bandAliasing;
  // Shimmer: this frame against the one measured just before it (consecutive frames only). When
  // the camera moved, this frame's shadows drawn again from the previous camera (`redrawn`: at the
  // previous frame's very points), or where the lesson cannot, each pixel against the previous
  // frame's sample of the same world point (`reprojected`; `unmatched`: pixels whose point that
  // frame did not see).
  bool hasTemporal = false;
  measure::TemporalErrors temporal;
  double recentMean = 0;  // the extra flips (soft: extra change) over the last `recentFrames` compared in a row
  int recentFrames = 0;
  bool redrawn = false;
  bool reprojected = false;
  std::size_t unmatched = 0;
  std::size_t nonFiniteVisibility = 0;  // covered pixels whose V is NaN or infinite (a broken matrix)
  std::size_t nonFiniteJacobian = 0;    // covered pixels whose texel Jacobian is (else they pass for background)
  double groundTruthMs = 0, readbackMs = 0, buildMs = 0;
  int width = 0, height = 0;  // the resolution measured at
  Image8 errorHeatmap, aliasingHeatmap, referenceImage;
};

class Measurement {
 public:
  Measurement();
  ~Measurement();
  void declare(ParamRegistry& params);
  // True when the frame should go through the measurement target this frame.
  bool active() const;
  int measuredLight() const { return active() ? light_ : -1; }
  // Take another measurement's settings (the A/B split measures B like A).
  void mirror(const Measurement& other) {
    overlay_ = other.overlay_;
    light_ = other.light_;
    scale_ = other.scale_;
    samples_ = other.samples_;
    seed_ = other.seed_;
    noiseFloor_ = other.noiseFloor_;
    live_ = other.live_;
    forceFull_ = forceFull_ || other.forceFull_;  // a full-resolution request of its own stays
  }
  // Force a full-resolution measurement of the next frame (headless --measure).
  void requestFullResolution() { forceFull_ = true; }

  // Before the lesson renders: the framebuffer it should draw into (the measurement target when
  // active, else `frameFbo`). `frame`: its size and the camera it draws with (the shimmer figures
  // compare the same world points from frame to frame when it moves).
  unsigned begin(unsigned frameFbo, const FrameInfo& frame);
  // After it rendered: copies the colour into `frameFbo`, measures if needed, draws the overlay.
  // `redraw` (Lesson::redrawLit): this frame's shadows drawn again from another camera, so that the
  // shimmer figures compare the previous frame's very points when the camera moved.
  using Redraw = std::function<bool(const FrameInfo& frame)>;
  void end(const MeasureSource& source, unsigned frameFbo, bool viewChanged, const Redraw& redraw = {});

  const MeasureResult& result() const { return result_; }
  // One-line figures for the header.
  std::vector<std::pair<std::string, std::string>> summary() const;
  // The shown overlay's colour key (none without an overlay).
  std::optional<Legend> legend() const;

 private:
  void ensureTarget(int width, int height);
  struct Readback {
    ImageF position, normal, jacobian;
  };
  void compute(const MeasureSource& source, const Redraw& redraw);
  void compareWithLastFrame(const ImageF& technique, const ImageF& reference, const ImageF& position,
                            const measure::SurfaceBuffer& surface, const Light& light, const Redraw& redraw);
  std::optional<ImageF> techniqueFromLastCamera(const Redraw& redraw);
  void fadeShimmer(const std::vector<std::uint8_t>& flipped, std::size_t pixels);
  Readback readBack(int factor);
  void ensureTruth(const MeasureSource& source);
  void measureAliasing(ImageF jacobian, const std::vector<std::uint8_t>& covered);
  void uploadOverlay();
  void drawOverlay(unsigned frameFbo);

  enum class Overlay { None, Error, Aliasing, Reference, Figures, Shimmer };
  Overlay overlay_ = Overlay::None;
  int light_ = 0;
  int scale_ = 2;
  int samples_ = 16;
  int seed_ = 1;             // the soft reference's sample seed
  bool noiseFloor_ = false;  // trace a second soft reference (another seed) and report their RMSE
  bool live_ = true;
  bool forceFull_ = false;
  bool dirty_ = true;

  int width_ = 0, height_ = 0;
  gl::Framebuffer fbo_;
  gl::Texture color_, position_, normal_, jacobian_, depth_;
  gl::Texture overlayTexture_;
  gl::VertexArray emptyVao_;
  gl::Program overlayProgram_{"measurement overlay", {"common/fullscreen.vert", "common/overlay.frag"}};
  std::unique_ptr<measure::GroundTruth> truth_;
  const Scene* truthScene_ = nullptr;
  std::uint64_t truthRevision_ = 0;
  std::map<std::string, Image8> textures_;
  MeasureResult result_;
  // The last measured frame's visibilities, for the shimmer figures.
  std::uint64_t frame_ = 0, lastMeasured_ = 0;
  int lastLight_ = -1;
  ImageF lastTechnique_, lastReference_, lastPosition_;
  measure::SurfaceBuffer lastSurface_;
  Light lastLightState_;
  int factor_ = 1;                   // the last measurement's subsampling
  std::vector<double> recent_;       // shimmer of the last frames compared in a row (the header's mean)
  std::vector<float> shimmerHeat_;   // the shimmer overlay: 1 where a pixel flipped this frame, fading after
  FrameInfo frameInfo_, lastFrame_;  // this frame's and the last measured frame's (size, camera)
};

}  // namespace shadowlab

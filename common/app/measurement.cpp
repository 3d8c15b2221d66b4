#include "app/measurement.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <initializer_list>

#include "core/paths.hpp"
#include "gl/caps.hpp"
#include "gl/gl.hpp"
#include "gl/texture.hpp"
#include "measure/ground_truth.hpp"
#include "measure/metrics.hpp"

namespace shadowlab {
namespace {

double nowMs() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// Reads one float attachment of the bound read framebuffer, top row first.
ImageF readFloat(GLenum attachment, GLenum format, int channels, int w, int h) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  std::vector<float> raw(std::size_t(w) * h * channels);
  if (attachment != GL_NONE) glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, format, GL_FLOAT, raw.data());
  img.data.resize(raw.size());
  const std::size_t row = std::size_t(w) * channels;
  for (int y = 0; y < h; ++y)
    std::memcpy(&img.data[std::size_t(y) * row], &raw[std::size_t(h - 1 - y) * row], row * sizeof(float));
  return img;
}

// The centre sample of each factor x factor block, as measure::downsample picks it, so the surface
// and the technique's images stay aligned pixel for pixel.
ImageF subsample(const ImageF& in, int factor) {
  if (factor == 1) return in;
  ImageF out;
  out.width = (in.width + factor - 1) / factor;
  out.height = (in.height + factor - 1) / factor;
  out.channels = in.channels;
  out.data.resize(std::size_t(out.width) * out.height * out.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < in.channels; ++c)
        out.at(x, y, c) =
            in.at(std::min(x * factor + factor / 2, in.width - 1), std::min(y * factor + factor / 2, in.height - 1), c);
  return out;
}

gl::Texture floatAttachment(GLenum internal, int w, int h, const std::string& label) {
  gl::Texture t = gl::makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

}  // namespace

Measurement::Measurement() = default;
Measurement::~Measurement() = default;

void Measurement::declare(ParamRegistry& r) {
  r.addChoice("measure.overlay", &overlay_, {"none", "error", "aliasing", "reference", "figures", "shimmer"},
              "compare with ground truth (Embree rays from the shaded points): leaks red, false shadows blue; "
              "figures: the header's figures over the lit picture, no overlay; shimmer: yellow where the shadow "
              "flipped from frame to frame and the ground truth's did not, fading over about 30 frames")
      .hotkey = "M";
  // The lesson's lights are declared before (lightN.kind): the range is theirs, so a light the
  // lesson lacks is refused like every other bad value (exit 2), overlay or not.
  int lights = 0;
  while (r.has("light" + std::to_string(lights) + ".kind")) ++lights;
  r.add("measure.light", &light_, 0, std::max(lights - 1, 0), "which of the lesson's lights is measured");
  r.add("measure.scale", &scale_, 1, 8, "measure every n-th pixel: 1 exact, larger stays interactive");
  r.add("measure.samples", &samples_, 1, 1024, "rays per pixel toward an area light (soft shadows)");
  r.add("measure.seed", &seed_, 1, 1000000, "the soft reference's sample seed (another seed: another noise)");
  r.add("measure.noise_floor", &noiseFloor_,
        "also trace a second soft reference with another seed: their RMSE is the reference's own noise");
  r.add("measure.live", &live_, "re-measure whenever the view or a parameter changes");
}

bool Measurement::active() const { return overlay_ != Overlay::None || forceFull_; }

void Measurement::ensureTarget(int w, int h) {
  if (fbo_ && w == width_ && h == height_) return;
  width_ = w;
  height_ = h;
  color_ = gl::makeTexture(GL_TEXTURE_2D, "measure.color");
  glBindTexture(GL_TEXTURE_2D, color_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  position_ = floatAttachment(GL_RGBA32F, w, h, "measure.position");
  normal_ = floatAttachment(GL_RGBA32F, w, h, "measure.normal+visibility");
  jacobian_ = floatAttachment(GL_RGBA32F, w, h, "measure.jacobian");
  depth_ = gl::makeTexture(GL_TEXTURE_2D, "measure.depth");
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, w, h, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  fbo_ = gl::makeFramebuffer("measurement target");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, position_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, normal_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, jacobian_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(4, buffers);
  gl::requireComplete(GL_FRAMEBUFFER, "measurement target");
  dirty_ = true;
}

// A browser has no ground truth (Embree runs natively): the overlays and figures say so and the
// frame is drawn as it is, without the surfaces the ground truth would read back.
constexpr const char* kNoTruthInBrowser = "ground truth: run the lesson natively (make run)";

unsigned Measurement::begin(unsigned frameFbo, const FrameInfo& frame) {
  frameInfo_ = frame;
  const int w = frame.width, h = frame.height;
  if (active() && gl::caps().gles) result_ = {}, result_.unmeasurable = kNoTruthInBrowser;
  if (!active() || gl::caps().gles) return frameFbo;
  if (!overlayProgram_.valid()) overlayProgram_.build();
  if (!emptyVao_) emptyVao_ = gl::makeVertexArray("fullscreen triangle");
  ensureTarget(w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  // The lesson clears colour with its own clear colour; these must start empty everywhere.
  const float zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 1, zero);
  glClearBufferfv(GL_COLOR, 2, zero);
  glClearBufferfv(GL_COLOR, 3, zero);
  return fbo_.id();
}

void Measurement::end(const MeasureSource& source, unsigned frameFbo, bool viewChanged, const Redraw& redraw) {
  if (!active() || gl::caps().gles) return;
  // The lesson's picture goes where the frame belongs.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frameFbo);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);

  ++frame_;
  if (viewChanged && live_) dirty_ = true;
  if (dirty_ || forceFull_) {
    compute(source, redraw);
    dirty_ = false;
    forceFull_ = false;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, frameFbo);
  if (overlay_ != Overlay::None && overlay_ != Overlay::Figures) drawOverlay(frameFbo);
}

namespace {

// The ground truth's visibility as grey levels (background transparent).
Image8 referenceImage(const ImageF& reference) {
  Image8 out;
  out.width = reference.width;
  out.height = reference.height;
  out.data.resize(std::size_t(reference.width) * reference.height * 4);
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    const float v = reference.data[i];
    const auto g = std::uint8_t(v < 0 ? 40 : std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    std::uint8_t* px = &out.data[i * 4];
    px[0] = px[1] = px[2] = g;
    px[3] = v == measure::kBackground ? 0 : 255;
  }
  return out;
}

// The technique's own V of the measured light, from the normal attachment's w.
ImageF techniqueVisibility(const ImageF& normal) {
  ImageF technique;
  technique.width = normal.width;
  technique.height = normal.height;
  technique.channels = 1;
  technique.data.resize(std::size_t(normal.width) * normal.height);
  for (std::size_t i = 0; i < technique.data.size(); ++i) technique.data[i] = normal.data[i * 4 + 3];
  return technique;
}

}  // namespace

// 1. read back what the rasteriser shaded (position.w marks covered pixels)
Measurement::Readback Measurement::readBack(int factor) {
  const double t0 = nowMs();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  Readback r;
  r.position = subsample(readFloat(GL_COLOR_ATTACHMENT1, GL_RGBA, 4, width_, height_), factor);
  // Coverage from depth: the lesson's glClear paints its clear colour (alpha 1) into every
  // attachment, so position.w alone cannot tell the sky from a surface.
  const ImageF depth = subsample(readFloat(GL_NONE, GL_DEPTH_COMPONENT, 1, width_, height_), factor);
  for (std::size_t i = 0; i < depth.data.size(); ++i)
    if (!(depth.data[i] < 1.0f)) r.position.data[i * 4 + 3] = 0.0f;
  r.normal = subsample(readFloat(GL_COLOR_ATTACHMENT2, GL_RGBA, 4, width_, height_), factor);
  r.jacobian = subsample(readFloat(GL_COLOR_ATTACHMENT3, GL_RGBA, 4, width_, height_), factor);
  result_.readbackMs = nowMs() - t0;
  return r;
}

// 2. the BVH, rebuilt only when the lesson's scene changed
void Measurement::ensureTruth(const MeasureSource& source) {
  for (const Material& m : source.scene->materials)
    if (m.alphaCutoff > 0 && !m.texture.empty() && !textures_.count(m.texture))
      textures_[m.texture] = loadImage(texturePath(m.texture), 4);
  if (!truth_ || truthScene_ != source.scene || truthRevision_ != source.sceneRevision) {
    truth_ = std::make_unique<measure::GroundTruth>(*source.scene, textures_);
    truthScene_ = source.scene;
    truthRevision_ = source.sceneRevision;
    result_.buildMs = truth_->lastBuildMs();
  }
}

// 4. aliasing, for techniques that sample a shadow map (their Jacobian is non-zero)
void Measurement::measureAliasing(ImageF jacobian, const std::vector<std::uint8_t>& covered) {
  bool anyJ = false;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    if (!covered[i]) {
      for (int c = 0; c < 4; ++c) jacobian.data[i * 4 + c] = std::nanf("");  // background
    } else {
      bool finite = true;
      for (int c = 0; c < 4; ++c) {
        anyJ = anyJ || jacobian.data[i * 4 + c] != 0.0f;
        finite = finite && std::isfinite(jacobian.data[i * 4 + c]);
      }
      result_.nonFiniteJacobian += !finite;  // NaN would otherwise pass for background below
    }
  }
  result_.hasAliasing = anyJ;
  if (anyJ) {
    result_.aliasing = measure::aliasingStats(jacobian);
    result_.aliasingHeatmap = measure::aliasingHeatmap(jacobian);
  }
}

// Shimmer: against the frame measured just before this one, when it was the previous frame, of the
// same light, at the same resolution (a still view is not re-measured: nothing moved). When the
// camera moved, this frame's shadows drawn again from the previous camera put them at the previous
// frame's very points (and the reference there, traced again if the light moved too); a lesson that
// cannot redraw is compared point by point through reprojection.
void Measurement::compareWithLastFrame(const ImageF& technique, const ImageF& reference, const ImageF& position,
                                       const measure::SurfaceBuffer& surface, const Light& light,
                                       const Redraw& redraw) {
  result_.hasTemporal = lastMeasured_ + 1 == frame_ && lastLight_ == light_ &&
                        lastTechnique_.width == technique.width && lastTechnique_.height == technique.height &&
                        !lastTechnique_.data.empty();
  const glm::mat4 viewProj = frameInfo_.projection * frameInfo_.view,
                  lastViewProj = lastFrame_.projection * lastFrame_.view;
  const bool moved = result_.hasTemporal && viewProj != lastViewProj;
  const std::optional<ImageF> again = moved ? techniqueFromLastCamera(redraw) : std::nullopt;
  // The extra flips pixel by pixel, for the shimmer overlay only (not through reprojection).
  std::vector<std::uint8_t> flipped;
  std::vector<std::uint8_t>* flippedAt = overlay_ == Overlay::Shimmer ? &flipped : nullptr;
  if (again) {
    const bool lightMoved = light.position != lastLightState_.position || light.direction != lastLightState_.direction;
    ImageF traced;  // the reference at the last frame's points under this frame's light, when it moved
    if (lightMoved)
      traced = result_.soft ? truth_->softVisibility(lastSurface_, light, samples_, std::uint64_t(seed_))
                            : truth_->hardVisibility(lastSurface_, light);
    result_.redrawn = true;
    result_.temporal = measure::compareFrames(lastTechnique_, *again, lastReference_,
                                              lightMoved ? traced : lastReference_, 0.5f, flippedAt);
  } else if (moved) {
    result_.reprojected = true;
    const measure::ReprojectedTemporalErrors r =
        measure::compareFramesReprojected({&lastTechnique_, &lastReference_, &lastPosition_, lastViewProj},
                                          {&technique, &reference, &position, viewProj});
    result_.temporal = r.errors;
    result_.unmatched = r.unmatched;
  } else if (result_.hasTemporal) {
    result_.temporal = measure::compareFrames(lastTechnique_, technique, lastReference_, reference, 0.5f, flippedAt);
  }
  if (flippedAt) fadeShimmer(flipped, technique.data.size());
  else shimmerHeat_.clear();
  // A mean over the last 30 frames in a row: one frame's flips come and go with the texel grid.
  if (!result_.hasTemporal) recent_.clear();
  else recent_.push_back(result_.soft ? result_.temporal.extraChange : result_.temporal.extraFlipPct);
  if (recent_.size() > 30) recent_.erase(recent_.begin());
  result_.recentFrames = int(recent_.size());
  for (const double v : recent_) result_.recentMean += v / double(recent_.size());
  lastTechnique_ = technique;
  lastReference_ = reference;
  lastPosition_ = position;
  lastSurface_ = surface;
  lastLightState_ = light;
  lastFrame_ = frameInfo_;
  lastMeasured_ = frame_;
  lastLight_ = light_;
}

// The shimmer overlay's heat: this frame's extra flips at 1, earlier ones fading by kShimmerFade a
// measured frame (a tenth left after 30). Redrawn, the flips sit at the previous frame's pixels: a
// slow camera moves less than a pixel a frame. Reprojected (a lesson that cannot redraw), nothing
// new lights up; a break in the run of compared frames starts it again.
void Measurement::fadeShimmer(const std::vector<std::uint8_t>& flipped, std::size_t pixels) {
  constexpr float kShimmerFade = 0.93f;
  if (!result_.hasTemporal || shimmerHeat_.size() != pixels) shimmerHeat_.assign(pixels, 0.0f);
  for (std::size_t i = 0; i < pixels; ++i)
    shimmerHeat_[i] = i < flipped.size() && flipped[i] ? 1.0f : shimmerHeat_[i] * kShimmerFade;
}

// This frame's shadows drawn from the last measured frame's camera into the measurement target,
// their V read back at the same resolution; nothing when the lesson cannot.
std::optional<ImageF> Measurement::techniqueFromLastCamera(const Redraw& redraw) {
  if (!redraw || lastFrame_.width != width_ || lastFrame_.height != height_) return std::nullopt;
  FrameInfo again = frameInfo_;
  again.view = lastFrame_.view;
  again.projection = lastFrame_.projection;
  again.eye = lastFrame_.eye;
  again.framebuffer = fbo_.id();
  again.measureLight = light_;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  const float zero[4] = {0, 0, 0, 0};
  for (int a = 1; a <= 3; ++a) glClearBufferfv(GL_COLOR, a, zero);
  if (!redraw(again)) return std::nullopt;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  return techniqueVisibility(subsample(readFloat(GL_COLOR_ATTACHMENT2, GL_RGBA, 4, width_, height_), factor_));
}

void Measurement::compute(const MeasureSource& source, const Redraw& redraw) {
  result_ = {};
  if (!source.scene || source.lights.empty() || !source.unmeasurable.empty()) {
    result_.unmeasurable = source.unmeasurable;
    overlayTexture_.reset();  // no heatmap of an earlier picture over this one
    return;
  }
  if (light_ >= int(source.lights.size()))
    throw std::runtime_error("measure.light = " + std::to_string(light_) + ", but the lesson has " +
                             std::to_string(source.lights.size()) + " light(s): valid 0.." +
                             std::to_string(source.lights.size() - 1));
  factor_ = forceFull_ ? 1 : scale_;
  const Readback shaded = readBack(factor_);
  ensureTruth(source);

  // 3. rays from the very points that were shaded
  const measure::SurfaceBuffer surface = measure::surfaceFromImages(shaded.position, shaded.normal);
  const ImageF technique = techniqueVisibility(shaded.normal);
  for (std::size_t i = 0; i < surface.covered.size(); ++i)
    result_.nonFiniteVisibility += surface.covered[i] && !std::isfinite(technique.data[i]);
  const Light& light = source.lights[std::size_t(light_)];
  result_.width = surface.width;
  result_.height = surface.height;
  result_.soft = light.area != AreaShape::None;
  const ImageF reference = result_.soft ? truth_->softVisibility(surface, light, samples_, std::uint64_t(seed_))
                                        : truth_->hardVisibility(surface, light);
  result_.groundTruthMs = truth_->lastQueryMs();
  if (result_.soft) {
    result_.soft_ = measure::compareSoft(technique, reference);
    if (noiseFloor_) {
      const ImageF second = truth_->softVisibility(surface, light, samples_, std::uint64_t(seed_) + 7919);
      result_.soft_.noiseFloor = measure::compareSoft(second, reference).rmse;
      result_.groundTruthMs += truth_->lastQueryMs();
    }
    result_.errorHeatmap = measure::softErrorHeatmap(technique, reference);
  } else {
    result_.hard = measure::compareHard(technique, reference);
    result_.errorHeatmap = measure::hardErrorHeatmap(technique, reference);
  }
  measureAliasing(shaded.jacobian, surface.covered);
  if (source.edgeBand > 0.0f && !result_.soft) {  // the same figures near shadow edges
    const auto band = measure::shadowEdgeBand(reference, shaded.position, light, source.edgeBand);
    result_.hasBand = true;
    result_.bandRadius = source.edgeBand;
    result_.band = measure::compareHard(technique, reference, band);
    if (result_.hasAliasing) result_.bandAliasing = measure::aliasingStats(measure::keepWhere(shaded.jacobian, band));
  }
  compareWithLastFrame(technique, reference, shaded.position, surface, light, redraw);
  result_.referenceImage = referenceImage(reference);
  result_.valid = true;
  uploadOverlay();
}

void Measurement::uploadOverlay() {
  Image8 shimmer;
  if (overlay_ == Overlay::Shimmer) shimmer = measure::shimmerHeatmap(shimmerHeat_, result_.width, result_.height);
  const Image8* shown = overlay_ == Overlay::Figures     ? nullptr
                        : overlay_ == Overlay::Aliasing  ? (result_.hasAliasing ? &result_.aliasingHeatmap : nullptr)
                        : overlay_ == Overlay::Reference ? &result_.referenceImage
                        : overlay_ == Overlay::Shimmer   ? &shimmer
                                                         : &result_.errorHeatmap;
  // The heatmaps' and the visibility's bytes are what to show: no sRGB decode on the way.
  if (shown) overlayTexture_ = gl::uploadTexture(*shown, "measurement overlay", false, gl::ColorData::Linear);
  else overlayTexture_.reset();
  if (overlayTexture_) {
    glBindTexture(GL_TEXTURE_2D, overlayTexture_.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
}

void Measurement::drawOverlay(unsigned frameFbo) {
  if (!overlayTexture_ || !overlayProgram_.valid()) return;
  glBindFramebuffer(GL_FRAMEBUFFER, frameFbo);
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  overlayProgram_.use();
  overlayProgram_.set("uOpacity", overlay_ == Overlay::Reference ? 1.0f : 0.85f);
  overlayProgram_.set("uOverlay", 0);
  // The overlay image is top row first and uploaded unflipped; the fullscreen triangle's v runs
  // bottom to top, so flip it here.
  overlayProgram_.set("uFlip", 1);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, overlayTexture_.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::countDraws();
  glDisable(GL_BLEND);
}

namespace {
glm::vec3 toColor(measure::Rgb8 c) { return glm::vec3(c.r, c.g, c.b) / 255.0f; }
}  // namespace

std::optional<Legend> Measurement::legend() const {
  if (!result_.unmeasurable.empty()) return std::nullopt;  // no overlay: no key to it
  if (overlay_ == Overlay::Error)
    return Legend{"error against ground truth",
                  {{toColor(measure::kLeakColor), "light leak: lit, should be shadowed"},
                   {toColor(measure::kFalseShadowColor), "false shadow: shadowed, should be lit"}}};
  if (overlay_ == Overlay::Shimmer)
    return Legend{"shimmer from frame to frame",
                  {{toColor(measure::kShimmerColor), "flipped, the ground truth did not"}}};
  if (overlay_ == Overlay::Aliasing) {
    Legend l{"aliasing m: screen pixels per shadow texel", {}};
    for (const auto& [m, label] :
         std::initializer_list<std::pair<float, const char*>>{{1.0f / 16, "1/16"},
                                                              {0.25f, "1/4"},
                                                              {1.0f, "1: alias-free up to here"},
                                                              {2.0f, "2"},
                                                              {4.0f, "4"},
                                                              {8.0f, "8"},
                                                              {16.0f, "16 and more"}})
      l.entries.push_back({toColor(measure::aliasingColor(m)), std::string("m = ") + label});
    return l;
  }
  return std::nullopt;
}

std::vector<std::pair<std::string, std::string>> Measurement::summary() const {
  std::vector<std::pair<std::string, std::string>> out;
  if (!active() && !result_.valid) return out;
  if (!result_.valid) {
    out.push_back({"measure", result_.unmeasurable.empty() ? "no scene or lights to measure" : result_.unmeasurable});
    return out;
  }
  char buf[160];
  if (result_.soft) {
    std::snprintf(buf, sizeof buf, "RMSE %.4f, max %.3f (%zu px)", result_.soft_.rmse, result_.soft_.maxAbs,
                  result_.soft_.pixels);
    out.push_back({"soft error", buf});
    std::snprintf(buf, sizeof buf, "over %.2f%%, under %.2f%% of px; bleeding %.2f%% of it", result_.soft_.umbraOverPct,
                  result_.soft_.umbraUnderPct, result_.soft_.bleedPct);
    out.push_back({"umbra", buf});
    if (result_.soft_.noiseFloor >= 0) {
      std::snprintf(buf, sizeof buf, "RMSE %.4f between two seeds", result_.soft_.noiseFloor);
      out.push_back({"reference noise", buf});
    }
  } else {
    const auto& h = result_.hard;
    std::snprintf(buf, sizeof buf, "%.2f%% (leaks %.2f%%, false shadows %.2f%%)", h.misclassifiedPct, h.leakPct,
                  h.falseShadowPct);
    out.push_back({"misclassified", buf});
    std::snprintf(buf, sizeof buf, "%.2f%% of %zu facing px", h.edgeTolerantPct, h.facingPixels);
    out.push_back({"edge-tolerant", buf});
  }
  if (result_.hasAliasing) {
    const auto& a = result_.aliasing;
    std::snprintf(buf, sizeof buf, "mean %.2f p95 %.2f max %.1f, m>1 %.1f%%", a.mean, a.p95, a.max,
                  100.0 * a.shareAbove1);
    out.push_back({"aliasing m", buf});
  }
  if (result_.hasTemporal) {  // against the previous frame
    const auto& t = result_.temporal;
    // The mean first: one frame's flips come and go as edges cross texel boundaries.
    if (result_.soft)
      std::snprintf(buf, sizeof buf, "|dV| %.4f a frame beyond the reference's, mean of %d", result_.recentMean,
                    result_.recentFrames);
    else
      std::snprintf(buf, sizeof buf, "%.3f%% of px flip a frame, mean of %d (reference %.3f%%)", result_.recentMean,
                    result_.recentFrames, t.referenceFlipPct);
    out.push_back({"shimmer", buf});
  }
  std::snprintf(buf, sizeof buf, "%dx%d: rays %.0f ms, read-back %.0f ms%s", result_.width, result_.height,
                result_.groundTruthMs, result_.readbackMs, result_.buildMs > 0 ? ", BVH rebuilt" : "");
  out.push_back({"ground truth", buf});
  return out;
}

}  // namespace shadowlab

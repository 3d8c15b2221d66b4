#pragma once
// Error and aliasing figures of a shadow technique against the ground truth (ground_truth.hpp).
// All images are top row first and pixel-aligned with the reference; sizes must match.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.hpp"
#include "core/light.hpp"

namespace shadowlab::measure {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

// ---- Hard shadows ------------------------------------------------------------------------------
// Counted over the pixels that face the light (reference >= 0, i.e. not kNotFacing/kBackground,
// or the explicit facing mask). A technique pixel is lit when its value >= litThreshold.
//   leak:         technique lit, reference shadowed (light where there should be shadow)
//   false shadow: technique shadowed, reference lit
// The edge-tolerant figure ignores pixels within 1 pixel (8-neighbourhood) of a reference shadow
// boundary, i.e. facing pixels with a facing neighbour of the other reference class.
struct HardShadowErrors {
  std::size_t facingPixels = 0;
  std::size_t referenceShadowed = 0;  // facing pixels the reference shadows (leaks are a share of these)
  std::size_t misclassified = 0, leaks = 0, falseShadows = 0;
  std::size_t edgePixels = 0;                                    // facing pixels excluded by the edge tolerance
  std::size_t edgeTolerantMisclassified = 0;                     // misclassified among the rest
  double misclassifiedPct = 0, leakPct = 0, falseShadowPct = 0;  // of facingPixels
  double edgeTolerantPct = 0;                                    // of facingPixels - edgePixels
};
HardShadowErrors compareHard(const ImageF& technique, const ImageF& reference, float litThreshold = 0.5f);
// `facing`: one byte per pixel, non-zero where the pixel faces the light (overrides the reference's
// own marks; reference values < 0 inside it count as shadowed).
HardShadowErrors compareHard(const ImageF& technique, const ImageF& reference, const std::vector<std::uint8_t>& facing,
                             float litThreshold = 0.5f);
// A technique's 8-bit lit mask (channel `channel`, 255 lit) as a visibility image in [0,1].
ImageF visibilityFromMask(const Image8& mask, int channel = 0);

// ---- Near shadow edges (lesson 07's figures) ---------------------------------------------------
// The facing pixels near a reference shadow edge: within `radius` of a boundary pixel (a facing
// pixel with a facing 8-neighbour of the other reference class), the distance measured across the
// light, i.e. in the plane perpendicular to the light's ray at the pixel, where a shadow map's
// texels lie: the direction of a directional light (radius in world units), or the ray from a
// spot or point light's position (radius a width at unit distance, times the pixel's distance to
// the light). So "within 2 texels of an edge" is one set of pixels for every technique measured
// on the same view: radius = 2 texels of one chosen map. Boundary pixels are searched within
// `window` screen pixels. `position`: 4 channels, the world positions of the shaded points.
// One byte per pixel, 1 inside. Throws std::invalid_argument for images of different sizes.
std::vector<std::uint8_t> shadowEdgeBand(const ImageF& reference, const ImageF& position, const Light& light,
                                         float radius, int window = 24);
// `image` with every pixel outside `mask` (one byte per pixel, 0 outside) set to NaN in all its
// channels: statistics that skip NaN then cover the mask only.
ImageF keepWhere(const ImageF& image, const std::vector<std::uint8_t>& mask);

// ---- Soft shadows ------------------------------------------------------------------------------
// The umbra is where (almost) none of the light is seen: visibility below `umbraLevel`. A technique
// over-estimates the umbra where it is black but the reference sees part of the light (a hard
// shadow kept as the umbra), and under-estimates it where the reference is black and it is not
// (a blurred umbra); both in % of the compared pixels.
inline constexpr float kUmbraLevel = 0.02f;
// Light bleeding: a pixel of the reference's umbra that the technique brightens by more than this
// (VSM's light through overlapping casters; issue 41's table), counted in % of the umbra.
inline constexpr float kBleedLevel = 0.1f;
struct SoftShadowErrors {
  std::size_t pixels = 0;  // facing pixels compared
  double rmse = 0;         // visibility units, [0,1]
  double maxAbs = 0;
  std::size_t umbraPixels = 0;  // the reference's umbra
  std::size_t umbraOver = 0, umbraUnder = 0;
  double umbraOverPct = 0, umbraUnderPct = 0;
  std::size_t bleed = 0;  // umbra pixels brightened by more than kBleedLevel
  double bleedPct = 0;    // ... in % of the reference's umbra
  // The reference's own noise: the RMSE between two references traced with different sample seeds
  // (measure.noise_floor); -1 when not measured. compareSoft leaves it alone.
  double noiseFloor = -1;
};
SoftShadowErrors compareSoft(const ImageF& technique, const ImageF& reference, float umbraLevel = kUmbraLevel);

// ---- Shimmer: two consecutive frames ----------------------------------------------------------
// Over the pixels that face the light in both frames: a hard shadow FLIPS at a pixel when its lit
// state (>= litThreshold) differs between the frames; the reference's own flips are where the
// shadow truly moved (a moving light, or the pixel now sees another point), the technique's
// further flips are shimmer. For soft shadows, the mean |V_now - V_before| beyond the reference's
// change at the same pixel. Throws std::invalid_argument for images of different sizes.
struct TemporalErrors {
  std::size_t pixels = 0;  // facing in both frames
  std::size_t flips = 0, referenceFlips = 0;
  std::size_t extraFlips = 0;                      // the technique flips, the reference does not
  double extraFlipPct = 0, referenceFlipPct = 0;   // of pixels
  double meanChange = 0, referenceMeanChange = 0;  // mean |dV| of the technique and of the reference
  double extraChange = 0;                          // mean max(|dV| - |dV_reference|, 0)
};
// `extraAt`, when given, becomes one byte a pixel: 1 where the technique flips and the reference does
// not (the pixels the shimmer overlay lights up), else 0.
TemporalErrors compareFrames(const ImageF& techniqueBefore, const ImageF& technique, const ImageF& referenceBefore,
                             const ImageF& reference, float litThreshold = 0.5f,
                             std::vector<std::uint8_t>* extraAt = nullptr);

// The same figures under a moving camera, where a pixel sees another world point each frame: each
// pixel is compared with the previous frame's pixel that saw ITS point (the point projected with the
// previous frame's view-projection, the sample whose block holds it), so a shadow edge fixed in the
// world (snapped maps) does not flip, and one that crawls over the geometry does. Pixels whose point
// the previous frame did not see (off screen, behind the camera, or hidden: the sample there lies
// farther from it than `footprints` times the largest spacing of that sample to its neighbours) are
// left out and counted. Positions are world space, one per pixel of the images (top row first), as
// the measurement reads them back.
struct FrameSamples {
  const ImageF* technique = nullptr;
  const ImageF* reference = nullptr;
  const ImageF* position = nullptr;  // RGBA: world xyz (w unused), the same size as the two above
  glm::mat4 viewProj{1.0f};          // the camera that drew them
};
struct ReprojectedTemporalErrors {
  TemporalErrors errors;
  std::size_t unmatched = 0;  // facing pixels now whose point the previous frame did not see
};
ReprojectedTemporalErrors compareFramesReprojected(const FrameSamples& before, const FrameSamples& now,
                                                   float footprints = 1.5f, float litThreshold = 0.5f);

// ---- Heatmaps (RGBA, alpha 255; 0 for background) ----------------------------------------------
inline constexpr Rgb8 kLeakColor{255, 48, 32};          // lit, should be shadowed
inline constexpr Rgb8 kFalseShadowColor{40, 110, 255};  // shadowed, should be lit
// Agreement is grey: lit 200, shadowed 110; not facing 50; background transparent black.
inline constexpr Rgb8 kShimmerColor{255, 214, 0};  // the shimmer overlay: flipped, the reference did not
// The shimmer overlay: kShimmerColor where `heat` (one value a pixel, top row first) is above 0, its
// alpha the heat (1: flipped this frame, fading after); transparent elsewhere, so the lit picture
// shows through. Throws std::invalid_argument when heat holds not width x height values.
Image8 shimmerHeatmap(const std::vector<float>& heat, int width, int height);
Image8 hardErrorHeatmap(const ImageF& technique, const ImageF& reference, float litThreshold = 0.5f);
// Signed soft error: too bright toward kLeakColor, too dark toward kFalseShadowColor, saturating at
// |error| = fullScale; a zero error shows the reference's visibility in grey.
Image8 softErrorHeatmap(const ImageF& technique, const ImageF& reference, float fullScale = 0.25f);

// ---- Aliasing ----------------------------------------------------------------------------------
// J maps a step of one screen pixel to shadow-map texels: J[0] = d(texel)/dx, J[1] = d(texel)/dy
// (GLM columns; in GLSL  mat2(dFdx(uv * size), dFdy(uv * size))). A texel then covers 1/sigma screen
// pixels along each singular direction, so the worst-stretched texel covers m = 1 / sigma_min(J)
// pixels; m <= 1 is alias-free. Singular J: +infinity.
float aliasingFactor(const glm::mat2& J);
float smallestSingularValue(const glm::mat2& J);

struct AliasingStats {
  std::size_t pixels = 0;  // pixels counted (finite inputs; NaN marks background)
  double mean = 0, rms = 0, p95 = 0, max = 0;
  double shareAbove1 = 0;  // fraction in [0,1] of pixels with m > 1
};
// `perPixel`: 1 channel of m values, or 4 channels (du/dx, dv/dx, du/dy, dv/dy) of J. NaN in any
// channel skips the pixel. m is capped at `cap` (a singular J would otherwise make the mean
// infinite). p95 is the nearest-rank percentile: the ceil(0.95 n)-th smallest value.
AliasingStats aliasingStats(const ImageF& perPixel, float cap = 1024.0f);
// Per-pixel m from a 4-channel J image (NaN stays NaN), or a copy of a 1-channel m image.
ImageF aliasingFactors(const ImageF& perPixel);

// m colour ramp on a log2 scale: m <= 1 in greens (darker toward m -> 0, 1/maxM and below the
// darkest), m > 1 from yellow (just above 1) through orange to red at maxM and beyond. NaN: black.
Rgb8 aliasingColor(float m, float maxM = 16.0f);
Image8 aliasingHeatmap(const ImageF& perPixel, float maxM = 16.0f);
// The values to label on a legend for aliasingHeatmap: 1/maxM, ..., 1/2, 1, 2, ..., maxM (powers of
// two; maxM rounded up to one).
std::vector<float> aliasingLegendTicks(float maxM = 16.0f);

}  // namespace shadowlab::measure

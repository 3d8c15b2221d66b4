#include "measure/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadowlab::measure {

namespace {

std::string sizeText(const ImageF& i) {
  return std::to_string(i.width) + "x" + std::to_string(i.height) + "x" + std::to_string(i.channels);
}

void checkImage(const ImageF& image, const char* what, const char* where) {
  if (image.width < 0 || image.height < 0 || image.channels < 1 ||
      image.data.size() != std::size_t(image.width) * image.height * image.channels)
    throw std::invalid_argument(std::string(where) + ": " + what + " image " + sizeText(image) + " holds " +
                                std::to_string(image.data.size()) + " values");
}

void checkPair(const ImageF& technique, const ImageF& reference, const char* where) {
  checkImage(technique, "technique", where);
  checkImage(reference, "reference", where);
  if (technique.width != reference.width || technique.height != reference.height || technique.channels != 1 ||
      reference.channels != 1)
    throw std::invalid_argument(std::string(where) + ": technique " + sizeText(technique) + " and reference " +
                                sizeText(reference) + " must be single-channel images of one size");
}

double pct(std::size_t part, std::size_t whole) { return whole ? 100.0 * double(part) / double(whole) : 0.0; }

HardShadowErrors compareHardImpl(const ImageF& technique, const ImageF& reference, const std::uint8_t* facing,
                                 float litThreshold) {
  const int w = reference.width, h = reference.height;
  auto isFacing = [&](int x, int y) {
    std::size_t i = std::size_t(y) * w + x;
    return facing ? facing[i] != 0 : reference.data[i] >= 0.0f;
  };
  // Reference class: lit (1) when >= 0.5; a reference is binary, values < 0 inside an explicit
  // facing mask count as shadowed.
  auto refLit = [&](int x, int y) { return reference.data[std::size_t(y) * w + x] >= 0.5f; };
  HardShadowErrors e;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!isFacing(x, y)) continue;
      ++e.facingPixels;
      bool lit = refLit(x, y);
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h || !isFacing(nx, ny)) continue;
          if (refLit(nx, ny) != lit) {
            edge = true;
            break;
          }
        }
      bool techLit = technique.data[std::size_t(y) * w + x] >= litThreshold;
      bool wrong = techLit != lit;
      e.referenceShadowed += !lit;
      if (wrong) {
        ++e.misclassified;
        if (techLit) ++e.leaks;
        else ++e.falseShadows;
      }
      if (edge) ++e.edgePixels;
      else if (wrong) ++e.edgeTolerantMisclassified;
    }
  e.misclassifiedPct = pct(e.misclassified, e.facingPixels);
  e.leakPct = pct(e.leaks, e.facingPixels);
  e.falseShadowPct = pct(e.falseShadows, e.facingPixels);
  e.edgeTolerantPct = pct(e.edgeTolerantMisclassified, e.facingPixels - e.edgePixels);
  return e;
}

}  // namespace

std::vector<std::uint8_t> shadowEdgeBand(const ImageF& reference, const ImageF& position, const Light& light,
                                         float radius, int window) {
  checkImage(reference, "reference", "shadowEdgeBand");
  checkImage(position, "position", "shadowEdgeBand");
  const int w = reference.width, h = reference.height;
  if (reference.channels != 1 || position.channels < 3 || position.width != w || position.height != h)
    throw std::invalid_argument("shadowEdgeBand: reference " + sizeText(reference) + " and position " +
                                sizeText(position) + " must be one size (1 and 3+ channels)");
  auto facing = [&](int x, int y) { return reference.data[std::size_t(y) * w + x] >= 0.0f; };
  auto lit = [&](int x, int y) { return reference.data[std::size_t(y) * w + x] >= 0.5f; };
  // Boundary pixels, and their summed-area table for a quick "any boundary near" test.
  std::vector<std::uint32_t> sat(std::size_t(w + 1) * std::size_t(h + 1), 0u);
  std::vector<std::uint8_t> boundary(std::size_t(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool edge = false;
      for (int dy = -1; dy <= 1 && facing(x, y); ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < w && ny < h && facing(nx, ny) && lit(nx, ny) != lit(x, y)) edge = true;
        }
      boundary[std::size_t(y) * w + x] = edge;
      sat[std::size_t(y + 1) * (w + 1) + x + 1] = edge + sat[std::size_t(y) * (w + 1) + x + 1] +
                                                  sat[std::size_t(y + 1) * (w + 1) + x] -
                                                  sat[std::size_t(y) * (w + 1) + x];
    }
  auto boundariesIn = [&](int x0, int y0, int x1, int y1) {  // inclusive, clamped
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, w - 1), y1 = std::min(y1, h - 1);
    return sat[std::size_t(y1 + 1) * (w + 1) + x1 + 1] - sat[std::size_t(y0) * (w + 1) + x1 + 1] -
           sat[std::size_t(y1 + 1) * (w + 1) + x0] + sat[std::size_t(y0) * (w + 1) + x0];
  };
  auto world = [&](int x, int y) {
    const float* p = &position.data[(std::size_t(y) * w + x) * std::size_t(position.channels)];
    return glm::vec3(p[0], p[1], p[2]);
  };
  const bool directional = light.kind == LightKind::Directional;
  std::vector<std::uint8_t> band(std::size_t(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!facing(x, y) || boundariesIn(x - window, y - window, x + window, y + window) == 0) continue;
      const glm::vec3 p = world(x, y);
      const glm::vec3 ray = directional ? glm::normalize(light.direction) : glm::normalize(p - light.position);
      const float r = directional ? radius : radius * glm::length(p - light.position);
      bool near = false;
      for (int qy = std::max(y - window, 0); qy <= std::min(y + window, h - 1) && !near; ++qy)
        for (int qx = std::max(x - window, 0); qx <= std::min(x + window, w - 1) && !near; ++qx) {
          if (!boundary[std::size_t(qy) * w + qx]) continue;
          glm::vec3 d = world(qx, qy) - p;
          d -= glm::dot(d, ray) * ray;
          near = glm::dot(d, d) <= r * r;
        }
      band[std::size_t(y) * w + x] = near;
    }
  return band;
}

ImageF keepWhere(const ImageF& image, const std::vector<std::uint8_t>& mask) {
  checkImage(image, "image", "keepWhere");
  if (mask.size() != std::size_t(image.width) * image.height)
    throw std::invalid_argument("keepWhere: a mask of " + std::to_string(mask.size()) + " pixels for " +
                                sizeText(image));
  ImageF out = image;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (!mask[i])
      for (int c = 0; c < image.channels; ++c)
        out.data[i * std::size_t(image.channels) + std::size_t(c)] = std::nanf("");
  return out;
}

namespace {

std::uint8_t lerp8(std::uint8_t a, std::uint8_t b, float t) {
  return std::uint8_t(std::lround(a + (float(b) - float(a)) * std::clamp(t, 0.0f, 1.0f)));
}
Rgb8 mix(Rgb8 a, Rgb8 b, float t) { return {lerp8(a.r, b.r, t), lerp8(a.g, b.g, t), lerp8(a.b, b.b, t)}; }

Image8 blank(int w, int h) {
  Image8 out;
  out.width = w;
  out.height = h;
  out.channels = 4;
  out.data.assign(std::size_t(w) * h * 4, 0);
  return out;
}
void put(Image8& image, std::size_t i, Rgb8 c) {
  image.data[4 * i] = c.r;
  image.data[4 * i + 1] = c.g;
  image.data[4 * i + 2] = c.b;
  image.data[4 * i + 3] = 255;
}

}  // namespace

HardShadowErrors compareHard(const ImageF& technique, const ImageF& reference, float litThreshold) {
  checkPair(technique, reference, "compareHard");
  return compareHardImpl(technique, reference, nullptr, litThreshold);
}

HardShadowErrors compareHard(const ImageF& technique, const ImageF& reference, const std::vector<std::uint8_t>& facing,
                             float litThreshold) {
  checkPair(technique, reference, "compareHard");
  if (facing.size() != reference.data.size())
    throw std::invalid_argument("compareHard: facing mask holds " + std::to_string(facing.size()) + " entries for " +
                                std::to_string(reference.data.size()) + " pixels");
  return compareHardImpl(technique, reference, facing.data(), litThreshold);
}

ImageF visibilityFromMask(const Image8& mask, int channel) {
  if (channel < 0 || channel >= mask.channels)
    throw std::invalid_argument("visibilityFromMask: channel " + std::to_string(channel) + " of a " +
                                std::to_string(mask.channels) + "-channel image");
  if (mask.data.size() != std::size_t(mask.width) * mask.height * mask.channels)
    throw std::invalid_argument("visibilityFromMask: mask data size " + std::to_string(mask.data.size()) +
                                " does not match its size");
  ImageF out;
  out.width = mask.width;
  out.height = mask.height;
  out.data.resize(std::size_t(mask.width) * mask.height);
  for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = mask.data[i * mask.channels + channel] / 255.0f;
  return out;
}

SoftShadowErrors compareSoft(const ImageF& technique, const ImageF& reference, float umbraLevel) {
  checkPair(technique, reference, "compareSoft");
  SoftShadowErrors e;
  double sum = 0;
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    if (!(reference.data[i] >= 0.0f)) continue;
    double d = double(technique.data[i]) - double(reference.data[i]);
    sum += d * d;
    e.maxAbs = std::max(e.maxAbs, std::abs(d));
    ++e.pixels;
    const bool refUmbra = reference.data[i] < umbraLevel, techUmbra = technique.data[i] < umbraLevel;
    e.umbraPixels += refUmbra;
    e.umbraOver += techUmbra && !refUmbra;
    e.umbraUnder += refUmbra && !techUmbra;
    e.bleed += refUmbra && d > double(kBleedLevel);
  }
  e.rmse = e.pixels ? std::sqrt(sum / double(e.pixels)) : 0.0;
  e.umbraOverPct = e.pixels ? 100.0 * double(e.umbraOver) / double(e.pixels) : 0.0;
  e.umbraUnderPct = e.pixels ? 100.0 * double(e.umbraUnder) / double(e.pixels) : 0.0;
  e.bleedPct = e.umbraPixels ? 100.0 * double(e.bleed) / double(e.umbraPixels) : 0.0;
  return e;
}

namespace {

// One pixel's two frames at a time, then the shares: compareFrames and its reprojected form.
struct FlipCount {
  TemporalErrors e;
  double change = 0, referenceChange = 0, extra = 0;
  float litThreshold = 0.5f;
  // True when the technique flips here and the reference does not.
  bool add(float t0, float t1, float r0, float r1) {
    ++e.pixels;
    const bool flip = (t0 >= litThreshold) != (t1 >= litThreshold);
    const bool referenceFlip = (r0 >= 0.5f) != (r1 >= 0.5f);
    e.flips += flip;
    e.referenceFlips += referenceFlip;
    e.extraFlips += flip && !referenceFlip;
    const double d = std::abs(double(t1) - double(t0)), dr = std::abs(double(r1) - double(r0));
    change += d;
    referenceChange += dr;
    extra += std::max(d - dr, 0.0);
    return flip && !referenceFlip;
  }
  TemporalErrors done() {
    if (e.pixels) {
      const double n = double(e.pixels);
      e.extraFlipPct = 100.0 * double(e.extraFlips) / n;
      e.referenceFlipPct = 100.0 * double(e.referenceFlips) / n;
      e.meanChange = change / n;
      e.referenceMeanChange = referenceChange / n;
      e.extraChange = extra / n;
    }
    return e;
  }
};

}  // namespace

TemporalErrors compareFrames(const ImageF& techniqueBefore, const ImageF& technique, const ImageF& referenceBefore,
                             const ImageF& reference, float litThreshold, std::vector<std::uint8_t>* extraAt) {
  checkPair(technique, reference, "compareFrames");
  checkPair(techniqueBefore, referenceBefore, "compareFrames");
  checkPair(technique, techniqueBefore, "compareFrames");
  FlipCount count{.litThreshold = litThreshold};
  if (extraAt) extraAt->assign(reference.data.size(), 0);
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    const float r0 = referenceBefore.data[i], r1 = reference.data[i];
    if (!(r0 >= 0.0f) || !(r1 >= 0.0f)) continue;
    const bool extra = count.add(techniqueBefore.data[i], technique.data[i], r0, r1);
    if (extraAt) (*extraAt)[i] = extra;
  }
  return count.done();
}

ReprojectedTemporalErrors compareFramesReprojected(const FrameSamples& before, const FrameSamples& now,
                                                   float footprints, float litThreshold) {
  if (!before.technique || !before.reference || !before.position || !now.technique || !now.reference || !now.position)
    throw std::invalid_argument("compareFramesReprojected: an image is missing");
  checkPair(*now.technique, *now.reference, "compareFramesReprojected");
  checkPair(*before.technique, *before.reference, "compareFramesReprojected");
  checkPair(*now.technique, *before.technique, "compareFramesReprojected");
  const int w = now.reference->width, h = now.reference->height;
  for (const ImageF* p : {before.position, now.position})
    if (p->width != w || p->height != h || p->channels != 4)
      throw std::invalid_argument("compareFramesReprojected: positions are not RGBA " + std::to_string(w) + "x" +
                                  std::to_string(h));
  ReprojectedTemporalErrors out;
  FlipCount count{.litThreshold = litThreshold};
  const auto point = [](const ImageF& p, std::size_t i) {
    return glm::vec4(p.data[4 * i], p.data[4 * i + 1], p.data[4 * i + 2], 1.0f);
  };
  for (std::size_t i = 0; i < now.reference->data.size(); ++i) {
    const float r1 = now.reference->data[i];
    if (!(r1 >= 0.0f)) continue;
    // Where the previous camera saw this pixel's point: its sample there (top row first).
    const glm::vec4 world = point(*now.position, i);
    const glm::vec4 clip = before.viewProj * world;
    const float fx = (clip.x / clip.w * 0.5f + 0.5f) * float(w), fy = (clip.y / clip.w * 0.5f + 0.5f) * float(h);
    bool seen = clip.w > 0.0f && fx >= 0.0f && fx < float(w) && fy >= 0.0f && fy < float(h);  // NaN: false
    std::size_t j = 0;
    if (seen) {
      const int px = int(fx), py = h - 1 - int(fy);
      j = std::size_t(py) * std::size_t(w) + std::size_t(px);
      // Hidden then: that sample's point lies farther from this one than its neighbours on the same
      // surface lie from it (those within 4x the nearest one: across a silhouette, not).
      const glm::vec3 there(point(*before.position, j));
      float gaps[4], nearest = INFINITY, spacing = 0.0f;
      int n = 0;
      for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
        const int nx = px + d.x, ny = py + d.y;
        const std::size_t k = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
        if (nx >= 0 && nx < w && ny >= 0 && ny < h && before.reference->data[k] >= 0.0f)
          nearest = std::min(nearest, gaps[n++] = glm::distance(there, glm::vec3(point(*before.position, k))));
      }
      for (int k = 0; k < n; ++k)
        if (gaps[k] <= 4.0f * nearest) spacing = std::max(spacing, gaps[k]);
      seen = before.reference->data[j] >= 0.0f && glm::distance(there, glm::vec3(world)) <= footprints * spacing;
    }
    if (!seen) {
      ++out.unmatched;
      continue;
    }
    count.add(before.technique->data[j], now.technique->data[i], before.reference->data[j], r1);
  }
  out.errors = count.done();
  return out;
}

Image8 hardErrorHeatmap(const ImageF& technique, const ImageF& reference, float litThreshold) {
  checkPair(technique, reference, "hardErrorHeatmap");
  Image8 out = blank(reference.width, reference.height);
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    float r = reference.data[i];
    if (r < -1.5f) continue;  // background
    if (r < 0.0f) {
      put(out, i, {50, 50, 50});
      continue;
    }
    bool refLit = r >= 0.5f, techLit = technique.data[i] >= litThreshold;
    if (techLit && !refLit) put(out, i, kLeakColor);
    else if (!techLit && refLit) put(out, i, kFalseShadowColor);
    else put(out, i, refLit ? Rgb8{200, 200, 200} : Rgb8{110, 110, 110});
  }
  return out;
}

Image8 shimmerHeatmap(const std::vector<float>& heat, int width, int height) {
  if (width < 0 || height < 0 || heat.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("shimmerHeatmap: " + std::to_string(heat.size()) + " values for " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels");
  Image8 out = blank(width, height);
  for (std::size_t i = 0; i < heat.size(); ++i)
    if (heat[i] > 0.0f) {
      put(out, i, kShimmerColor);
      out.data[4 * i + 3] = std::uint8_t(std::lround(255.0f * std::min(heat[i], 1.0f)));
    }
  return out;
}

Image8 softErrorHeatmap(const ImageF& technique, const ImageF& reference, float fullScale) {
  checkPair(technique, reference, "softErrorHeatmap");
  if (!(fullScale > 0.0f))
    throw std::invalid_argument("softErrorHeatmap: fullScale " + std::to_string(fullScale) + " must be > 0");
  Image8 out = blank(reference.width, reference.height);
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    float r = reference.data[i];
    if (r < -1.5f) continue;
    if (r < 0.0f) {
      put(out, i, {50, 50, 50});
      continue;
    }
    std::uint8_t g = std::uint8_t(std::lround(90 + 110 * std::clamp(r, 0.0f, 1.0f)));
    float d = technique.data[i] - r;
    float t = std::min(std::abs(d) / fullScale, 1.0f);
    put(out, i, mix({g, g, g}, d > 0 ? kLeakColor : kFalseShadowColor, t));
  }
  return out;
}

float smallestSingularValue(const glm::mat2& J) {
  double a = J[0][0], b = J[0][1], c = J[1][0], d = J[1][1];
  double s = a * a + b * b + c * c + d * d;
  double det = a * d - b * c;
  double disc = std::sqrt(std::max(0.0, s * s - 4 * det * det));
  double sigmaMax = std::sqrt((s + disc) / 2);
  // |det| / sigma_max is sigma_min without the cancellation of (s - disc) / 2.
  return sigmaMax > 0 ? float(std::abs(det) / sigmaMax) : 0.0f;
}

float aliasingFactor(const glm::mat2& J) {
  float sigma = smallestSingularValue(J);
  if (std::isnan(sigma)) return std::numeric_limits<float>::quiet_NaN();
  return sigma > 0.0f ? 1.0f / sigma : std::numeric_limits<float>::infinity();
}

ImageF aliasingFactors(const ImageF& perPixel) {
  checkImage(perPixel, "per-pixel", "aliasingFactors");
  if (perPixel.channels != 1 && perPixel.channels != 4)
    throw std::invalid_argument("aliasingFactors: " + std::to_string(perPixel.channels) +
                                " channels; need 1 (m) or 4 (du/dx, dv/dx, du/dy, dv/dy)");
  if (perPixel.channels == 1) return perPixel;
  ImageF out;
  out.width = perPixel.width;
  out.height = perPixel.height;
  out.data.resize(std::size_t(perPixel.width) * perPixel.height);
  for (std::size_t i = 0; i < out.data.size(); ++i) {
    const float* j = &perPixel.data[4 * i];
    bool nan = std::isnan(j[0]) || std::isnan(j[1]) || std::isnan(j[2]) || std::isnan(j[3]);
    out.data[i] = nan ? std::numeric_limits<float>::quiet_NaN()
                      : aliasingFactor(glm::mat2(glm::vec2(j[0], j[1]), glm::vec2(j[2], j[3])));
  }
  return out;
}

AliasingStats aliasingStats(const ImageF& perPixel, float cap) {
  if (!(cap >= 1.0f)) throw std::invalid_argument("aliasingStats: cap " + std::to_string(cap) + " must be >= 1");
  ImageF m = aliasingFactors(perPixel);
  std::vector<float> values;
  values.reserve(m.data.size());
  for (float v : m.data)
    if (!std::isnan(v)) values.push_back(std::min(v, cap));
  AliasingStats s;
  s.pixels = values.size();
  if (values.empty()) return s;
  double sum = 0, sum2 = 0;
  std::size_t above = 0;
  for (float v : values) {
    sum += v;
    sum2 += double(v) * v;
    above += v > 1.0f;
  }
  s.mean = sum / double(values.size());
  s.rms = std::sqrt(sum2 / double(values.size()));
  s.shareAbove1 = double(above) / double(values.size());
  std::size_t rank = std::size_t(std::ceil(0.95 * double(values.size())));
  rank = std::clamp<std::size_t>(rank, 1, values.size());
  std::nth_element(values.begin(), values.begin() + (rank - 1), values.end());
  s.p95 = values[rank - 1];
  s.max = *std::max_element(values.begin(), values.end());
  return s;
}

Rgb8 aliasingColor(float m, float maxM) {
  if (std::isnan(m)) return {0, 0, 0};
  float range = std::log2(std::max(maxM, 2.0f));
  float t = m > 0.0f ? std::log2(m) / range : -1.0f;  // -1 .. 1 over [1/maxM, maxM]
  if (m <= 1.0f) return mix({0, 70, 30}, {120, 225, 120}, 1.0f + std::max(t, -1.0f));
  t = std::min(t, 1.0f);
  if (t < 0.5f) return mix({255, 235, 0}, {255, 140, 0}, t * 2);
  return mix({255, 140, 0}, {210, 0, 0}, t * 2 - 1);
}

Image8 aliasingHeatmap(const ImageF& perPixel, float maxM) {
  ImageF m = aliasingFactors(perPixel);
  Image8 out = blank(m.width, m.height);
  for (std::size_t i = 0; i < m.data.size(); ++i)
    if (!std::isnan(m.data[i])) put(out, i, aliasingColor(m.data[i], maxM));
  return out;
}

std::vector<float> aliasingLegendTicks(float maxM) {
  int top = std::max(1, int(std::ceil(std::log2(std::max(maxM, 2.0f)))));
  std::vector<float> ticks;
  for (int k = -top; k <= top; ++k) ticks.push_back(std::ldexp(1.0f, k));
  return ticks;
}

}  // namespace shadowlab::measure

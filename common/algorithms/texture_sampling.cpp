#include "algorithms/texture_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadowlab::sampling {

namespace {
constexpr float kPi = 3.14159265358979323846f;

void requireSize(int w, int h, const char* what) {
  if (w < 1 || h < 1)
    throw std::invalid_argument(std::string(what) + ": size " + std::to_string(w) + "x" + std::to_string(h) +
                                " must be at least 1x1");
}

int levelsOf(int n) {
  int levels = 1;
  while (n > 1) {
    n /= 2;
    ++levels;
  }
  return levels;
}

// Sum of max(1, n >> k) over the levels of one axis.
std::uint64_t axisSum(int n) {
  std::uint64_t s = 0;
  for (int k = 0, levels = levelsOf(n); k < levels; ++k) s += std::uint64_t(std::max(1, n >> k));
  return s;
}

glm::vec4 read(const ImageF& img, int x, int y) {
  glm::vec4 v(0, 0, 0, 1);
  for (int c = 0; c < std::min(img.channels, 4); ++c) v[c] = img.at(x, y, c);
  return v;
}

ImageF blank(int w, int h, int channels) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.data.assign(std::size_t(w) * h * channels, 0.0f);
  return img;
}

void requireImage(const ImageF& img, const char* what) {
  if (img.width < 1 || img.height < 1 || img.channels < 1 ||
      img.data.size() != std::size_t(img.width) * img.height * img.channels)
    throw std::invalid_argument(std::string(what) + ": empty or inconsistent image (" + std::to_string(img.width) +
                                "x" + std::to_string(img.height) + "x" + std::to_string(img.channels) + ")");
}

// Averages the texels (2x + a, 2y + b) for a < fx, b < fy.
ImageF downsample(const ImageF& src, bool halveX, bool halveY, const char* what) {
  requireImage(src, what);
  const int w = halveX ? std::max(1, src.width / 2) : src.width;
  const int h = halveY ? std::max(1, src.height / 2) : src.height;
  const int fx = halveX && src.width > 1 ? 2 : 1, fy = halveY && src.height > 1 ? 2 : 1;
  ImageF dst = blank(w, h, src.channels);
  const float inv = 1.0f / float(fx * fy);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < src.channels; ++c) {
        float sum = 0;
        for (int b = 0; b < fy; ++b)
          for (int a = 0; a < fx; ++a) sum += src.at(x * fx + a, y * fy + b, c);
        dst.at(x, y, c) = sum * inv;
      }
  return dst;
}
}  // namespace

// ---- Mip chains and memory -----------------------------------------------------------------------
int mipLevelCount(int width, int height) {
  requireSize(width, height, "mipLevelCount");
  return levelsOf(std::max(width, height));
}

glm::ivec2 mipLevelSize(int width, int height, int level) {
  requireSize(width, height, "mipLevelSize");
  if (level < 0 || level >= mipLevelCount(width, height))
    throw std::invalid_argument("mipLevelSize: level " + std::to_string(level) + " outside [0, " +
                                std::to_string(mipLevelCount(width, height) - 1) + "]");
  return {std::max(1, width >> level), std::max(1, height >> level)};
}

std::uint64_t mipChainBytes(int width, int height, int bytesPerTexel) {
  requireSize(width, height, "mipChainBytes");
  std::uint64_t texels = 0;
  for (int l = 0, n = mipLevelCount(width, height); l < n; ++l)
    texels += std::uint64_t(std::max(1, width >> l)) * std::uint64_t(std::max(1, height >> l));
  return texels * std::uint64_t(bytesPerTexel);
}

std::uint64_t ripMapBytes(int width, int height, int bytesPerTexel) {
  requireSize(width, height, "ripMapBytes");
  return axisSum(width) * axisSum(height) * std::uint64_t(bytesPerTexel);
}

std::uint64_t volumeBytes(int width, int height, int depth, int bytesPerTexel) {
  requireSize(width, height, "volumeBytes");
  requireSize(depth, 1, "volumeBytes depth");
  return std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(depth) * std::uint64_t(bytesPerTexel);
}

ImageF boxDownsample(const ImageF& src) { return downsample(src, true, true, "boxDownsample"); }
ImageF boxDownsampleX(const ImageF& src) { return downsample(src, true, false, "boxDownsampleX"); }
ImageF boxDownsampleY(const ImageF& src) { return downsample(src, false, true, "boxDownsampleY"); }

std::vector<ImageF> buildMipChain(const ImageF& base) {
  requireImage(base, "buildMipChain");
  std::vector<ImageF> chain{base};
  while (chain.back().width > 1 || chain.back().height > 1) chain.push_back(boxDownsample(chain.back()));
  return chain;
}

ImageF toFloat(const Image8& image) {
  ImageF f = blank(image.width, image.height, 4);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      for (int c = 0; c < 4; ++c) f.at(x, y, c) = c < image.channels ? p[c] / 255.0f : 1.0f;
    }
  return f;
}

Image8 toImage8(const ImageF& image) {
  Image8 out;
  out.width = image.width;
  out.height = image.height;
  out.channels = 4;
  out.data.resize(std::size_t(image.width) * image.height * 4);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4 v = read(image, x, y);
      for (int c = 0; c < 4; ++c) out.at(x, y)[c] = std::uint8_t(std::lround(std::clamp(v[c], 0.0f, 1.0f) * 255.0f));
    }
  return out;
}

glm::ivec2 RipAtlas::levelSize(int i, int j) const {
  return {std::max(1, baseWidth >> i), std::max(1, baseHeight >> j)};
}

RipAtlas buildRipAtlas(const ImageF& base) {
  requireImage(base, "buildRipAtlas");
  RipAtlas r;
  r.baseWidth = base.width;
  r.baseHeight = base.height;
  r.levelsX = levelsOf(base.width);
  r.levelsY = levelsOf(base.height);
  int x = 0, y = 0;
  for (int i = 0; i < r.levelsX; ++i) r.offsetX.push_back(std::exchange(x, x + std::max(1, base.width >> i)));
  for (int j = 0; j < r.levelsY; ++j) r.offsetY.push_back(std::exchange(y, y + std::max(1, base.height >> j)));
  r.atlas = blank(x, y, base.channels);
  ImageF row = base;  // level (0, j), halved in y as j grows
  for (int j = 0; j < r.levelsY; ++j) {
    ImageF level = row;
    for (int i = 0; i < r.levelsX; ++i) {
      for (int ty = 0; ty < level.height; ++ty)
        for (int tx = 0; tx < level.width; ++tx)
          for (int c = 0; c < base.channels; ++c)
            r.atlas.at(r.offsetX[i] + tx, r.offsetY[j] + ty, c) = level.at(tx, ty, c);
      if (i + 1 < r.levelsX) level = boxDownsampleX(level);
    }
    if (j + 1 < r.levelsY) row = boxDownsampleY(row);
  }
  return r;
}

// ---- Level of detail and anisotropy -------------------------------------------------------------
Footprint footprint(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size, float maxAniso) {
  Footprint f;
  const glm::vec2 s(size);
  f.px = glm::length(dUVdx * s);
  f.py = glm::length(dUVdy * s);
  f.majorIsX = f.px >= f.py;
  f.pmax = std::max(f.px, f.py);
  f.pmin = std::min(f.px, f.py);
  f.lambda = f.pmax > 0 ? std::log2(f.pmax) : -std::numeric_limits<float>::infinity();
  const int maxN = std::max(1, int(std::floor(maxAniso)));
  if (f.pmax <= 0) f.probes = 1;
  else if (f.pmin <= 0) f.probes = maxN;
  else f.probes = int(std::min<double>(std::ceil(double(f.pmax) / double(f.pmin)), double(maxN)));
  f.lambdaAniso = f.pmax > 0 ? std::log2(f.pmax / float(f.probes)) : f.lambda;
  return f;
}

float lodFromDerivatives(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size) {
  return footprint(dUVdx, dUVdy, size).lambda;
}

// ---- Sampling ----------------------------------------------------------------------------------
int wrapIndex(int i, int n, Wrap wrap) {
  switch (wrap) {
    case Wrap::Repeat: return ((i % n) + n) % n;
    case Wrap::MirroredRepeat: {
      const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
    case Wrap::ClampToEdge: return std::clamp(i, 0, n - 1);
    case Wrap::ClampToBorder: return i < 0 || i >= n ? -1 : i;
  }
  return 0;
}

glm::vec4 texel(const ImageF& level, int x, int y, Wrap s, Wrap t, const glm::vec4& border) {
  const int wx = wrapIndex(x, level.width, s), wy = wrapIndex(y, level.height, t);
  if (wx < 0 || wy < 0) return border;
  return read(level, wx, wy);
}

glm::vec4 sampleNearest(const ImageF& level, const glm::vec2& uv, Wrap s, Wrap t, const glm::vec4& border) {
  const float u = uv.x * float(level.width), v = uv.y * float(level.height);
  return texel(level, int(std::floor(u)), int(std::floor(v)), s, t, border);
}

glm::vec4 sampleBilinear(const ImageF& level, const glm::vec2& uv, Wrap s, Wrap t, const glm::vec4& border) {
  const float u = uv.x * float(level.width) - 0.5f, v = uv.y * float(level.height) - 0.5f;
  const float fu = std::floor(u), fv = std::floor(v);
  const int i0 = int(fu), j0 = int(fv);
  const float a = u - fu, b = v - fv;
  const glm::vec4 t00 = texel(level, i0, j0, s, t, border), t10 = texel(level, i0 + 1, j0, s, t, border);
  const glm::vec4 t01 = texel(level, i0, j0 + 1, s, t, border), t11 = texel(level, i0 + 1, j0 + 1, s, t, border);
  return (1 - a) * (1 - b) * t00 + a * (1 - b) * t10 + (1 - a) * b * t01 + a * b * t11;
}

namespace {
glm::vec4 filterLevel(const ImageF& level, const glm::vec2& uv, Filter f, const SamplerState& s) {
  return f == Filter::Nearest ? sampleNearest(level, uv, s.wrapS, s.wrapT, s.border)
                              : sampleBilinear(level, uv, s.wrapS, s.wrapT, s.border);
}
}  // namespace

glm::vec4 sampleLod(const std::vector<ImageF>& chain, const glm::vec2& uv, float lambda, const SamplerState& s) {
  if (chain.empty()) throw std::invalid_argument("sampleLod: empty mip chain");
  const int q = int(chain.size()) - 1;
  if (!(lambda > 0.0f)) return filterLevel(chain[0], uv, s.mag, s);  // magnification (and NaN)
  switch (s.mip) {
    case MipFilter::None: return filterLevel(chain[0], uv, s.min, s);
    case MipFilter::Nearest: {
      // GL spec 8.14.3: d = 0 for lambda <= 1/2, else ceil(lambda + 1/2) - 1, at most q.
      const int d = lambda <= 0.5f ? 0 : std::min(q, int(std::ceil(lambda + 0.5f)) - 1);
      return filterLevel(chain[std::size_t(d)], uv, s.min, s);
    }
    case MipFilter::Linear: {
      if (lambda >= float(q)) return filterLevel(chain[std::size_t(q)], uv, s.min, s);
      const int d1 = int(std::floor(lambda));
      const float a = lambda - float(d1);
      return (1 - a) * filterLevel(chain[std::size_t(d1)], uv, s.min, s) +
             a * filterLevel(chain[std::size_t(d1 + 1)], uv, s.min, s);
    }
  }
  return glm::vec4(0);
}

SamplerState bestFilter(const SamplerState& s) {
  SamplerState best = s;
  best.mag = best.min = Filter::Linear;
  best.mip = MipFilter::Linear;
  best.maxAniso = 16;
  best.lodBias = 0;
  return best;
}

glm::vec4 sample(const std::vector<ImageF>& chain, const glm::vec2& uv, const glm::vec2& dUVdx, const glm::vec2& dUVdy,
                 const SamplerState& s) {
  if (chain.empty()) throw std::invalid_argument("sample: empty mip chain");
  const Footprint f = footprint(dUVdx, dUVdy, {chain[0].width, chain[0].height}, s.maxAniso);
  if (f.probes <= 1) return sampleLod(chain, uv, f.lambda + s.lodBias, s);
  // EXT_texture_filter_anisotropic: N probes along the major axis, at (i / (N + 1) - 1/2) of the
  // pixel's extent, i = 1..N, each read at lambda' = log2(Pmax / N); their mean.
  const glm::vec2 axis = f.majorIsX ? dUVdx : dUVdy;
  glm::vec4 sum(0);
  for (int i = 1; i <= f.probes; ++i)
    sum += sampleLod(chain, uv + axis * (float(i) / float(f.probes + 1) - 0.5f), f.lambdaAniso + s.lodBias, s);
  return sum / float(f.probes);
}

// ---- Projections ---------------------------------------------------------------------------------
glm::vec2 planarUv(const glm::vec3& p) { return {p.x, p.z}; }

glm::vec2 cylindricalUv(const glm::vec3& p) {
  float phi = std::atan2(p.x, p.z);
  if (phi < 0) phi += 2 * kPi;
  return {phi / (2 * kPi), p.y};
}

glm::vec2 sphericalUv(const glm::vec3& p) {
  const float r = glm::length(p);
  if (r == 0) return {0, 0};
  float phi = std::atan2(p.x, p.z);
  if (phi < 0) phi += 2 * kPi;
  return {phi / (2 * kPi), std::acos(std::clamp(p.y / r, -1.0f, 1.0f)) / kPi};
}

ImageF makeZonePlate(int size) {
  requireSize(size, size, "makeZonePlate");
  ImageF img = blank(size, size, 4);
  const float k = 1.0f / float(size);  // local frequency k r cycles/texel: the Nyquist 1/2 at r = size/2
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float dx = float(x) + 0.5f - 0.5f * float(size), dy = float(y) + 0.5f - 0.5f * float(size);
      const float v = 0.5f + 0.5f * std::cos(kPi * k * (dx * dx + dy * dy));
      img.at(x, y, 0) = img.at(x, y, 1) = img.at(x, y, 2) = v;
      img.at(x, y, 3) = 1.0f;
    }
  return img;
}

std::vector<std::uint8_t> makeShellVolume(int n) {
  requireSize(n, n, "makeShellVolume");
  std::vector<std::uint8_t> voxels(std::size_t(n) * n * n * 4);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::vec3 p = (glm::vec3(x, y, z) + 0.5f) / float(n) - 0.5f;
        const float d = 0.5f + 0.5f * std::cos(40.0f * glm::length(p) + 6.0f * p.x);
        std::uint8_t* v = &voxels[((std::size_t(z) * n + y) * n + x) * 4];
        v[0] = std::uint8_t(255 * d);
        v[1] = std::uint8_t(255 * d * d);
        v[2] = std::uint8_t(std::clamp(255 * (1 - d) * 0.6f + 60 * (p.z + 0.5f), 0.0f, 255.0f));
        v[3] = 255;
      }
  return voxels;
}

std::vector<float> boxReduceRgb(const Image8& image, int factor) {
  if (factor < 1 || image.width % factor || image.height % factor || image.channels < 3)
    throw std::invalid_argument("boxReduceRgb: " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " is not a multiple of " + std::to_string(factor) + " (or has no RGB)");
  const int w = image.width / factor, h = image.height / factor;
  std::vector<float> out(std::size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) {
        double acc = 0;
        for (int b = 0; b < factor; ++b)
          for (int a = 0; a < factor; ++a) acc += image.at(x * factor + a, y * factor + b)[k];
        out[(std::size_t(y) * w + x) * 3 + k] = float(acc / double(factor * factor));
      }
  return out;
}

double rmse(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.empty()) return -1;
  double se = 0;
  for (std::size_t i = 0; i < a.size(); ++i) se += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return std::sqrt(se / double(a.size()));
}

double meanAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.empty()) return -1;
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(double(a[i]) - b[i]);
  return sum / double(a.size());
}

}  // namespace shadowlab::sampling

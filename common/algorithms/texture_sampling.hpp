#pragma once
// Texture sampling on the CPU, GL-free: the maths of lesson 06 ([Tarantsev-L12], textures) written out
// so it can be unit-tested and compared with what the GPU does.
//
//   mip chains     sizes, level count, memory (4/3 of the base, not the lecture slide's 1.5)
//   RIP maps       every (u, v) halving pair: 4x the base; an atlas the shader reads with texelFetch
//   level of detail  lambda = log2(rho), rho = max(|d(uv)/dx|, |d(uv)/dy|) in texels (GL spec 8.14)
//   anisotropy     EXT_texture_filter_anisotropic: Px, Py, Pmax, Pmin, N = min(ceil(Pmax/Pmin),
//                  maxAniso), lambda' = log2(Pmax / N), N probes along the major axis
//   sampling       nearest, bilinear, the four mipmap modes, anisotropic; the four wrap modes
//   projections    planar, cylindrical, spherical texture coordinates
//
// Conventions: images are float RGBA (ImageF with channels 1..4; missing channels read 0, alpha 1).
// A texture's row 0 is t = 0, as glTexImage2D's first row: the sampler does NOT flip, so an image
// uploaded row 0 first samples identically on the GPU. Texel i covers u in [i/w, (i+1)/w), its
// centre at (i + 0.5)/w.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.hpp"

namespace shadowlab::sampling {

enum class Wrap { Repeat, MirroredRepeat, ClampToEdge, ClampToBorder };
enum class Filter { Nearest, Linear };
// Minification between levels: None (level 0 only), Nearest (one level), Linear (two levels).
enum class MipFilter { None, Nearest, Linear };

// ---- Mip chains and memory ---------------------------------------------------------------------
// floor(log2(max(w, h))) + 1: halving (floor, at least 1) until 1x1. Throws std::invalid_argument
// for a size < 1.
int mipLevelCount(int width, int height);
// Size of level `level` (max(1, w >> level), max(1, h >> level)).
glm::ivec2 mipLevelSize(int width, int height, int level);
// Bytes of the whole chain, every level at `bytesPerTexel`.
std::uint64_t mipChainBytes(int width, int height, int bytesPerTexel);
// Bytes of a RIP map: every level (i, j) of max(1, w >> i) x max(1, h >> j), i, j in [0, levels).
std::uint64_t ripMapBytes(int width, int height, int bytesPerTexel);
// A 3D texture: w h d bytesPerTexel (the lecture's 256^3 x 4 = 64 MiB).
std::uint64_t volumeBytes(int width, int height, int depth, int bytesPerTexel);

// One mip level from the one above: each dimension halved (floor, at least 1); every texel the
// mean of its 2x2 parents (1x2 or 2x1 where a dimension is already 1). An odd size drops its last
// row or column, as a plain box filter does. Throws std::invalid_argument on an empty image.
ImageF boxDownsample(const ImageF& src);
// Halving one axis only (RIP maps): x or y.
ImageF boxDownsampleX(const ImageF& src);
ImageF boxDownsampleY(const ImageF& src);
// Level 0 (a copy of `base`) to 1x1, built with boxDownsample.
std::vector<ImageF> buildMipChain(const ImageF& base);
// RGBA8 (rows as given) to float RGBA in [0,1].
ImageF toFloat(const Image8& image);
Image8 toImage8(const ImageF& image);

// RIP map in one atlas of (2w - 1) x (2h - 1) texels: level (i, j) at offset (x_i, y_j) with
// x_i = sum_{k<i} max(1, w >> k), likewise y_j.
struct RipAtlas {
  ImageF atlas;
  int baseWidth = 0, baseHeight = 0;
  int levelsX = 0, levelsY = 0;
  std::vector<int> offsetX, offsetY;  // per level i (x) and j (y)
  glm::ivec2 levelSize(int i, int j) const;
};
RipAtlas buildRipAtlas(const ImageF& base);

// ---- Level of detail and anisotropy (per pixel, from screen-space derivatives) ----------------
// Derivatives are of (u, v) in [0,1] units; `size` converts them to texels.
struct Footprint {
  float px = 0, py = 0;  // |d(uv)/dx|, |d(uv)/dy| in texels: the pixel's footprint axes
  float pmax = 0, pmin = 0;
  float lambda = 0;       // isotropic: log2(pmax) (GL's rho = max(px, py))
  int probes = 1;         // anisotropic N = min(ceil(pmax / pmin), maxAniso), 1 when isotropic
  float lambdaAniso = 0;  // log2(pmax / N): the level each probe reads
  bool majorIsX = true;   // probes step along d(uv)/dx (else d(uv)/dy)
};
// A zero footprint gives lambda = -infinity (pure magnification); pmin = 0 with pmax > 0 gives
// N = maxAniso (floor(maxAniso), at least 1).
Footprint footprint(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size, float maxAniso = 1.0f);
float lodFromDerivatives(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size);

// ---- Sampling ----------------------------------------------------------------------------------
struct SamplerState {
  Filter mag = Filter::Linear;
  Filter min = Filter::Linear;
  MipFilter mip = MipFilter::Linear;
  Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
  glm::vec4 border{0.0f};
  float lodBias = 0.0f;
  float maxAniso = 1.0f;  // 1: isotropic
};

// The best filter a sampler offers, `s`'s wrap modes and border kept: trilinear (linear
// magnification and minification, linear between levels), 16x anisotropy, no LOD bias. Lesson 06
// renders its supersampled reference with it.
SamplerState bestFilter(const SamplerState& s);

// Integer texel index after wrapping; -1 for clamp-to-border outside [0, n).
int wrapIndex(int i, int n, Wrap wrap);
glm::vec4 texel(const ImageF& level, int x, int y, Wrap s, Wrap t, const glm::vec4& border);
glm::vec4 sampleNearest(const ImageF& level, const glm::vec2& uv, Wrap s = Wrap::Repeat, Wrap t = Wrap::Repeat,
                        const glm::vec4& border = glm::vec4(0));
glm::vec4 sampleBilinear(const ImageF& level, const glm::vec2& uv, Wrap s = Wrap::Repeat, Wrap t = Wrap::Repeat,
                         const glm::vec4& border = glm::vec4(0));
// Minification at a given lambda with the sampler's min and mip filters (the four mipmap modes,
// and trilinear = Linear/Linear). lambda <= 0 uses the magnification filter on level 0.
glm::vec4 sampleLod(const std::vector<ImageF>& chain, const glm::vec2& uv, float lambda, const SamplerState& s);
// The full path: lambda from the derivatives (+ bias), then anisotropic probes when maxAniso > 1.
glm::vec4 sample(const std::vector<ImageF>& chain, const glm::vec2& uv, const glm::vec2& dUVdx, const glm::vec2& dUVdy,
                 const SamplerState& s);

// ---- Texture-coordinate projections ([Tarantsev-L12], projecting texture coordinates) ---------------
// Plane: (x, y) of the point in the projection's frame; here the xz ground plane: (x, z).
glm::vec2 planarUv(const glm::vec3& p);
// Cylinder around +y: (phi / 2pi, y), phi = atan2(x, z) in [0, 2pi).
glm::vec2 cylindricalUv(const glm::vec3& p);
// Sphere: (phi / 2pi, theta / pi), theta from +y (the north pole at v = 0). Origin: (0, 0).
glm::vec2 sphericalUv(const glm::vec3& p);

// A zone plate: cos(pi k r^2) rings whose frequency grows with the radius until it aliases at the
// border (the classic test for filtering). RGBA, `size` x `size`.
ImageF makeZonePlate(int size);

// A 3D texture of nested density shells (a stand-in tomogram): n^3 RGBA8 voxels, x fastest.
// Throws std::invalid_argument for n < 1.
std::vector<std::uint8_t> makeShellVolume(int n);

// ---- Image error figures (lesson 06's supersampled reference) ---------------------------------
// The RGB of an RGBA8 image as floats (0-255), each output pixel the mean of a factor x factor
// block; the size must divide by the factor (std::invalid_argument otherwise).
std::vector<float> boxReduceRgb(const Image8& image, int factor);
// Root mean square and mean absolute difference of two equally long arrays; -1 when the lengths
// differ or are 0 (the first frame has no previous one to flicker against).
double rmse(const std::vector<float>& a, const std::vector<float>& b);
double meanAbsDifference(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace shadowlab::sampling

#pragma once
// Lesson 06 exercises: texture filtering. Write them in exercises.cpp; grade with
//   make grade LESSON=06   (it builds what changed first)
// and see yours live with  lesson_06_texture_filtering --set impl=student --set view=cpu_reference
// (the CPU reference view then samples every pixel with YOUR functions).
//
// Conventions (as algorithms/texture_sampling.hpp): images are ImageF, float channels (1 to 4) in [0,1],
// img.at(x, y, c); row 0 is t = 0. Texel i covers u in [i/w, (i+1)/w); its centre is (i + 0.5)/w.
// Derivatives d(uv)/dx, d(uv)/dy are in uv units (multiply by the size for texels).
#include <vector>

#include <glm/glm.hpp>

#include "core/image.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex06 {

// EXERCISE 06.1: how many levels a full mip chain of a w x h texture has: halve each side (integer
// division, never below 1) until the level is 1x1, counting level 0 and the 1x1 level. The
// lecture's 256x64 chain has 9 levels ([Tarantsev-L12], "levels of detail (mipmap)").
int mipLevelCount(int width, int height);

// EXERCISE 06.2: the memory of that whole chain in bytes, every level w_l x h_l at bytesPerTexel.
// (The lecture's slide says 1.5x the base; work out what a square chain really costs.)
long long mipChainBytes(int width, int height, int bytesPerTexel);

// EXERCISE 06.3: the level of detail lambda = log2(rho) (GL spec 8.14), rho = max(Px, Py), with
// Px = |d(uv)/dx| and Py = |d(uv)/dy| measured in texels of a `size` texture (Euclidean lengths).
float lodFromDerivatives(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size);

// EXERCISE 06.4: bilinear filtering of one level with REPEAT wrapping: u' = u w - 1/2, v' = v h - 1/2,
// i0 = floor(u'), j0 = floor(v'), a = frac(u'), b = frac(v'); blend texels (i0, j0), (i0+1, j0),
// (i0, j0+1), (i0+1, j0+1) with weights (1-a)(1-b), a(1-b), (1-a)b, ab. Indices wrap modulo the
// size (negative ones too). Channels the image lacks are 0, except alpha, which is 1.
glm::vec4 sampleBilinear(const ImageF& level, const glm::vec2& uv);

// EXERCISE 06.5: trilinear filtering (GL_LINEAR_MIPMAP_LINEAR) at a given lambda over a chain:
// lambda <= 0: bilinear on level 0 (magnification); lambda >= q (the last level): bilinear on
// level q; else d = floor(lambda), blend bilinear(d) and bilinear(d + 1) by frac(lambda).
// Use your sampleBilinear.
glm::vec4 sampleTrilinear(const std::vector<ImageF>& chain, const glm::vec2& uv, float lambda);

// EXERCISE 06.6: EXT_texture_filter_anisotropic's probe count and level:
//   Px = |d(uv)/dx| texels, Py = |d(uv)/dy| texels, Pmax = max, Pmin = min,
//   N = min(ceil(Pmax / Pmin), maxAniso), lambda' = log2(Pmax / N).
// maxAniso is an integer >= 1 here. When Pmin = 0 (and Pmax > 0), N = maxAniso.
struct AnisoProbes {
  int count = 1;
  float lambda = 0;
};
AnisoProbes anisotropicProbes(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size, int maxAniso);

// EXERCISE 06.7: one mip level from the level above it with a box filter: each side halved
// (integer division, never below 1), each texel the mean of its parents (2x2; 2x1 or 1x2 where a
// side is already 1), for every channel. Same channel count as the source.
ImageF boxDownsample(const ImageF& src);

}  // namespace shadowlab::ex06

// The reference for lesson 06's graders: forwards to common/algorithms/texture_sampling (never a copy).
#include "exercises.hpp"

#include "algorithms/texture_sampling.hpp"

namespace shadowlab::ex06 {
int mipLevelCount(int w, int h) { return sampling::mipLevelCount(w, h); }
long long mipChainBytes(int w, int h, int bpp) { return (long long)sampling::mipChainBytes(w, h, bpp); }
float lodFromDerivatives(const glm::vec2& dx, const glm::vec2& dy, const glm::ivec2& size) {
  return sampling::lodFromDerivatives(dx, dy, size);
}
glm::vec4 sampleBilinear(const ImageF& level, const glm::vec2& uv) { return sampling::sampleBilinear(level, uv); }
glm::vec4 sampleTrilinear(const std::vector<ImageF>& chain, const glm::vec2& uv, float lambda) {
  return sampling::sampleLod(chain, uv, lambda, sampling::SamplerState{});
}
AnisoProbes anisotropicProbes(const glm::vec2& dx, const glm::vec2& dy, const glm::ivec2& size, int maxAniso) {
  const sampling::Footprint f = sampling::footprint(dx, dy, size, float(maxAniso));
  return {f.probes, f.lambdaAniso};
}
ImageF boxDownsample(const ImageF& src) { return sampling::boxDownsample(src); }
}  // namespace shadowlab::ex06

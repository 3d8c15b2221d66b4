// Lesson 06: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=06   (it builds what changed first)
#include "exercises.hpp"

#include <cmath>

namespace shadowlab::ex06 {

// EXERCISE 06.1
int mipLevelCount(int width, int height) {
  SHADOWLAB_STUB("06.1");  // delete this line when you write the exercise
  // TODO: count the levels down to 1x1
  return 1;
}

// EXERCISE 06.2
long long mipChainBytes(int width, int height, int bytesPerTexel) {
  SHADOWLAB_STUB("06.2");  // delete this line when you write the exercise
  // TODO: sum over the levels, not just level 0
  return (long long)width * height * bytesPerTexel;
}

// EXERCISE 06.3
float lodFromDerivatives(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size) {
  SHADOWLAB_STUB("06.3");  // delete this line when you write the exercise
  // TODO: log2(max(|dUVdx * size|, |dUVdy * size|))
  return 0.0f;
}

// EXERCISE 06.4
glm::vec4 sampleBilinear(const ImageF& level, const glm::vec2& uv) {
  SHADOWLAB_STUB("06.4");  // delete this line when you write the exercise
  // TODO: four texels, weights (1-a)(1-b), a(1-b), (1-a)b, ab, repeat wrapping
  return glm::vec4(0.0f);
}

// EXERCISE 06.5
glm::vec4 sampleTrilinear(const std::vector<ImageF>& chain, const glm::vec2& uv, float lambda) {
  SHADOWLAB_STUB("06.5");  // delete this line when you write the exercise
  // TODO: blend two levels by frac(lambda)
  return glm::vec4(0.0f);
}

// EXERCISE 06.6
AnisoProbes anisotropicProbes(const glm::vec2& dUVdx, const glm::vec2& dUVdy, const glm::ivec2& size, int maxAniso) {
  SHADOWLAB_STUB("06.6");  // delete this line when you write the exercise
  // TODO: N = min(ceil(Pmax / Pmin), maxAniso), lambda' = log2(Pmax / N)
  return {};
}

// EXERCISE 06.7
ImageF boxDownsample(const ImageF& src) {
  SHADOWLAB_STUB("06.7");  // delete this line when you write the exercise
  // TODO: halve each side, average the parents
  return src;
}

}  // namespace shadowlab::ex06

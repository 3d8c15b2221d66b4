// The reference for lesson 03's graders: forwards to common/algorithms/shadow_math (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex03 {
float slopeScaledBias(float c, float s, float cosTheta, float maxBias) {
  return shadow::slopeScaledBias(c, s, cosTheta, maxBias);
}
glm::vec4 bilinearPcfWeights(const glm::vec2& texel) { return shadow::bilinearPcfWeights(texel); }
int cubeFace(const glm::vec3& d) { return shadow::cubeFace(d); }
bool casterMayShadow(const Aabb& b, const shadow::ConvexVolume& v, const glm::vec3& d) {
  return shadow::casterMayShadow(b, v, d);
}
shadow::OrthoFit fitOrthographic(const glm::vec3& d, std::span<const glm::vec3> r, std::span<const Aabb> c, int size,
                                 bool snap) {
  return shadow::fitOrthographic(d, r, c, size, snap);
}
}  // namespace shadowlab::ex03

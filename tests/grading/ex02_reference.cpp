// The reference for lesson 02's graders: forwards to common/algorithms/shadow_math (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex02 {
glm::mat4 shadowTextureMatrix(const glm::mat4& P, const glm::mat4& V) { return shadow::textureMatrix(P, V); }
float depthCompare(float fragmentDepth, float storedDepth, float bias) {
  return shadow::depthCompare(fragmentDepth, storedDepth, bias);
}
float shadowLookup(const shadow::DepthMap& map, const glm::vec3& uvz, float bias) {
  return shadow::shadowLookup(map, uvz, bias);
}
}  // namespace shadowlab::ex02

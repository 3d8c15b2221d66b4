// The reference for lesson 04's graders: forwards to common/algorithms/shadow_volume (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex04 {
bool isSilhouette(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                  const glm::vec4& light) {
  return volume::isSilhouette(a, b, c, d, light);
}
glm::mat4 infinitePerspective(float fovY, float aspect, float nearZ, float epsilon) {
  return volume::infinitePerspective(fovY, aspect, nearZ, epsilon);
}
volume::StencilOps stencilOps(bool zFail) { return volume::stencilOps(zFail); }
bool volumeMayReachNearPlane(const Aabb& bounds, const volume::NearRect& near, const glm::vec4& light) {
  return volume::volumeMayReachNearPlane(bounds, near, light);
}
}  // namespace shadowlab::ex04

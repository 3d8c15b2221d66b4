// Lesson 04: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=04   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex04 {

// EXERCISE 04.1
bool isSilhouette(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                  const glm::vec4& light) {
  SHADOWLAB_STUB("04.1");  // delete this line when you write the exercise
  // TODO: does exactly one of (a, b, c) and (b, a, d) face the light?
  return false;
}

// EXERCISE 04.2
glm::mat4 infinitePerspective(float fovY, float aspect, float nearZ, float epsilon) {
  SHADOWLAB_STUB("04.2");  // delete this line when you write the exercise
  // TODO: the perspective matrix with its far plane at infinity
  return glm::mat4(1.0f);
}

// EXERCISE 04.3
volume::StencilOps stencilOps(bool zFail) {
  SHADOWLAB_STUB("04.3");  // delete this line when you write the exercise
  // TODO: z-pass counts where the depth test passes, z-fail where it fails
  return {};
}

// EXERCISE 04.4
bool volumeMayReachNearPlane(const Aabb& bounds, const volume::NearRect& near, const glm::vec4& light) {
  SHADOWLAB_STUB("04.4");  // delete this line when you write the exercise
  // TODO: is the box outside one plane of the hull of the near rectangle and the light?
  return false;
}

}  // namespace shadowlab::ex04

// Lesson 02: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=02   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex02 {

// EXERCISE 02.1
glm::mat4 shadowTextureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView) {
  SHADOWLAB_STUB("02.1");  // delete this line when you write the exercise
  // TODO: translate(0.5) * scale(0.5) * P_light * V_light
  return glm::mat4(1.0f);
}

// EXERCISE 02.2
float depthCompare(float fragmentDepth, float storedDepth, float bias) {
  SHADOWLAB_STUB("02.2");  // delete this line when you write the exercise
  // TODO: 1 when fragmentDepth - bias <= storedDepth, else 0
  return 1.0f;
}

// EXERCISE 02.3
float shadowLookup(const shadow::DepthMap& map, const glm::vec3& uvz, float bias) {
  SHADOWLAB_STUB("02.3");  // delete this line when you write the exercise
  // TODO: nearest texel, compared with depthCompare; lit outside the map
  return 1.0f;
}

}  // namespace shadowlab::ex02

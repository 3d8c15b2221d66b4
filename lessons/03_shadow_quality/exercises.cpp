// Lesson 03: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=03   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex03 {

// EXERCISE 03.1
float slopeScaledBias(float constant, float slope, float cosTheta, float maxBias) {
  SHADOWLAB_STUB("03.1");  // delete this line when you write the exercise
  // TODO: min(constant + slope * tan(theta), maxBias); maxBias when cosTheta <= 0
  return 0.0f;
}

// EXERCISE 03.2
glm::vec4 bilinearPcfWeights(const glm::vec2& texel) {
  SHADOWLAB_STUB("03.2");  // delete this line when you write the exercise
  // TODO: the bilinear weights of the four texels around texel - 0.5
  return glm::vec4(0.0f);
}

// EXERCISE 03.3
int cubeFace(const glm::vec3& direction) {
  SHADOWLAB_STUB("03.3");  // delete this line when you write the exercise
  // TODO: the major axis and its sign, in GL's face order
  return -1;
}

// EXERCISE 03.4
bool casterMayShadow(const Aabb& caster, const shadow::ConvexVolume& view, const glm::vec3& lightDirection) {
  SHADOWLAB_STUB("03.4");  // delete this line when you write the exercise
  // TODO: false when a plane has the box outside and the sweep does not move inward
  return true;
}

// EXERCISE 03.5
shadow::OrthoFit fitOrthographic(const glm::vec3& lightDirection, std::span<const glm::vec3> receivers,
                                 std::span<const Aabb> casters, int mapSize, bool snap) {
  SHADOWLAB_STUB("03.5");  // delete this line when you write the exercise
  // TODO: light view, bounds of the receivers, casters on the near side, glm::ortho
  return shadow::OrthoFit{};
}

}  // namespace shadowlab::ex03

// Lesson 05: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=05   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex05 {

// EXERCISE 05.1
float penumbraHalfWidth(float d, float nDotL, float R, float D) {
  SHADOWLAB_STUB("05.1");  // delete this line when you write the exercise
  // TODO: d / (n.L) * R / D
  return 0.0f;
}

// EXERCISE 05.2
float visibleFraction(float t) {
  SHADOWLAB_STUB("05.2");  // delete this line when you write the exercise
  // TODO: 1/2 + (t sqrt(1 - t^2) + asin t) / pi, t clamped to [-1, 1]
  return 0.5f;
}

// EXERCISE 05.2
float visibleFractionLinear(float t) {
  SHADOWLAB_STUB("05.2");  // delete this line when you write the exercise
  // TODO: (1 + t) / 2, t clamped to [-1, 1]
  return 0.5f;
}

// EXERCISE 05.3
float pcssFilterRadiusUv(float R, float zReceiver, float zBlocker, float tanHalfFov) {
  SHADOWLAB_STUB("05.3");  // delete this line when you write the exercise
  // TODO: (zReceiver - zBlocker) / zBlocker * R / (2 zReceiver tanHalfFov); 0 for a blocker behind
  return 0.0f;
}

// EXERCISE 05.4
glm::vec2 rotateTap(const glm::vec2& tap, float angle) {
  SHADOWLAB_STUB("05.4");  // delete this line when you write the exercise
  // TODO: turn the tap by angle (counter-clockwise)
  return tap;
}

// EXERCISE 05.5
float lightMeshVisibility(const soft::LightGrid& grid, const glm::vec3& p) {
  SHADOWLAB_STUB("05.5");  // delete this line when you write the exercise
  // TODO: the trilinear average of the 8 nodes around p
  return 1.0f;
}

// EXERCISE 05.7
double msmLitShare(const glm::dvec4& moments, double t, double alpha) {
  SHADOWLAB_STUB("05.7");  // delete this line when you write the exercise
  // TODO: bias b, solve B c = (1, t, t^2), the roots z1 <= z2, the weight in front of t
  (void)moments;
  (void)t;
  (void)alpha;
  return 1.0;
}

}  // namespace shadowlab::ex05

// Lesson 09: your solutions. Each function says what to return in exercises.hpp; grade with
//   make grade LESSON=09   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex09 {

// EXERCISE 09.1
glm::dmat4 inverseProjection(double fovY, double aspect, double a) {
  SHADOWLAB_STUB("09.1");  // delete this line when you write the exercise
  // TODO: x, y like a perspective of fovY/aspect; clip z = a (times the input w); clip w = -z_view.
  (void)fovY;
  (void)aspect;
  (void)a;
  return glm::dmat4(1.0);
}

// EXERCISE 09.2
glm::dvec4 smallestEnclosingCone(const std::vector<glm::dvec3>& directions) {
  SHADOWLAB_STUB("09.2");  // delete this line when you write the exercise
  // TODO: normalise, find the smallest ball around the unit vectors, axis = its centre normalised,
  // halfAngle = the largest angle between the axis and a direction.
  (void)directions;
  return glm::dvec4(0.0);
}

// EXERCISE 09.3
bool cubeFaceVisible(int face, const glm::dvec4& postLight) {
  SHADOWLAB_STUB("09.3");  // delete this line when you write the exercise
  // TODO: the face's outward normal n; finite light: dot(n, p) >= 1; direction: dot(n, D) >= 0.
  (void)face;
  (void)postLight;
  return false;
}

// EXERCISE 09.4
glm::dvec3 texelSizeBias(const glm::dmat4& worldToClip, const glm::dvec3& p, const glm::dvec3& dirFromLight, double a,
                         double b, double mapSize) {
  SHADOWLAB_STUB("09.4");  // delete this line when you write the exercise
  // TODO: L_texel = |P - unproject(M P shifted by one texel in x and y)|; P + L (a + b L_texel).
  (void)worldToClip;
  (void)dirFromLight;
  (void)a;
  (void)b;
  (void)mapSize;
  return p * 0.0;
}

// EXERCISE 09.5
double lispsmOptimalN(double z0, double z1, double gamma) {
  SHADOWLAB_STUB("09.5");  // delete this line when you write the exercise
  // TODO: (z0 + sqrt(z0 z1)) / |sin(gamma)|, or +infinity when sin(gamma) == 0.
  (void)z0;
  (void)z1;
  (void)gamma;
  return 0.0;
}

}  // namespace shadowlab::ex09

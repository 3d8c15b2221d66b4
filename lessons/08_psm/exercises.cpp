// Lesson 08: your solutions. Each function says what to return in exercises.hpp; grade with
//   make grade LESSON=08   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex08 {

// EXERCISE 08.1
glm::dvec4 postProjectiveLight(const glm::dmat4& viewProj, const glm::dvec4& light) {
  SHADOWLAB_STUB("08.1");  // delete this line when you write the exercise
  // TODO: h = viewProj * light; classify by the sign of h.w (with the 1e-9 tolerance) and return
  // (h.xyz / h.w, +-1) or (normalize(h.xyz), 0).
  (void)viewProj;
  (void)light;
  return glm::dvec4(0.0);
}

// EXERCISE 08.2
double virtualCameraShift(const glm::dmat4& view, double zNear, const std::vector<glm::dvec3>& casterCorners) {
  SHADOWLAB_STUB("08.2");  // delete this line when you write the exercise
  // TODO: the largest z_view + zNear over the corners (z_view = (view * (corner, 1)).z), or 0.
  (void)view;
  (void)zNear;
  (void)casterCorners;
  return 0.0;
}

}  // namespace shadowlab::ex08

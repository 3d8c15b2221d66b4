// The reference for lesson 05's graders: forwards to common/algorithms/soft_shadows (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex05 {
float penumbraHalfWidth(float d, float nDotL, float R, float D) { return soft::penumbraHalfWidth(d, nDotL, R, D); }
float visibleFraction(float t) { return soft::visibleFraction(t); }
float visibleFractionLinear(float t) { return soft::visibleFractionLinear(t); }
float pcssFilterRadiusUv(float R, float zr, float zb, float tanHalfFov) {
  return soft::pcssFilterRadiusUv(R, zr, zb, tanHalfFov);
}
glm::vec2 rotateTap(const glm::vec2& tap, float angle) { return soft::rotateTap(tap, angle); }
float lightMeshVisibility(const soft::LightGrid& grid, const glm::vec3& p) {
  return soft::lightMeshVisibility(grid, p);
}
double msmLitShare(const glm::dvec4& moments, double t, double alpha) { return soft::msmLitShare(moments, t, alpha); }
}  // namespace shadowlab::ex05

#include "algorithms/psm/bias.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "algorithms/psm/conventions.hpp"

namespace shadowlab::psm {

glm::dmat4 texelOffsetMatrix(const glm::dmat4& M, const glm::dvec2& size) {
  requireFinite(M, "worldToClip");
  if (!(size.x >= 1.0) || !(size.y >= 1.0) || !std::isfinite(size.x) || !std::isfinite(size.y))
    throw std::invalid_argument("mapSize = (" + std::to_string(size.x) + ", " + std::to_string(size.y) +
                                ") must be at least 1 texel");
  const glm::dmat4 inv = glm::inverse(M);
  if (!isFinite(inv)) throw std::invalid_argument("worldToClip is singular");
  glm::dmat4 cMinusI(0.0);
  cMinusI[3][0] = 2.0 / size.x;
  cMinusI[3][1] = 2.0 / size.y;
  return inv * cMinusI * M;
}

TexelStep texelStepFactors(const glm::dmat4& M, const glm::dvec2& size) {
  texelOffsetMatrix(M, size);  // the same checks (finite, invertible, at least one texel)
  TexelStep t;
  t.u = glm::inverse(M) * glm::dvec4(2.0 / size.x, 2.0 / size.y, 0.0, 0.0);
  t.r = glm::dvec4(M[0][3], M[1][3], M[2][3], M[3][3]);
  return t;
}

double texelWorldSize(const glm::dmat4& K, const glm::dvec3& p) {
  const glm::dvec4 d = K * glm::dvec4(p, 1.0);
  // w <= 0: the one-texel step crossed the camera's plane at infinity (a texel at the far end of
  // a PSM with a huge Zf/Zn): the texel is unbounded in world space.
  if (!(1.0 + d.w > 0.0)) return std::numeric_limits<double>::infinity();
  const glm::dvec3 shifted = (p + glm::dvec3(d)) / (1.0 + d.w);
  return glm::length(shifted - p);
}

double texelWorldSizePaper(const glm::dmat4& K, const glm::dvec3& p) {
  const glm::dvec3 d(K * glm::dvec4(p, 1.0));
  return glm::dot(d, d);
}

glm::dvec3 biasedWorldPoint(const glm::dvec3& p, const glm::dvec3& dirFromLight, double a, double b, double texelSize,
                            double maxOffset) {
  if (!(a >= 0.0) || !(b >= 0.0) || !std::isfinite(a) || !std::isfinite(b))
    throw std::invalid_argument("bias coefficients a, b must be finite and >= 0");
  if (std::isnan(texelSize) || texelSize < 0.0)
    throw std::invalid_argument("texelSize = " + std::to_string(texelSize) + " is invalid");
  if (!(maxOffset >= 0.0)) throw std::invalid_argument("maxOffset = " + std::to_string(maxOffset) + " must be >= 0");
  const double len = glm::length(dirFromLight);
  if (!(len > 0.0) || !std::isfinite(len)) throw std::invalid_argument("dirFromLight must be a finite non-zero vector");
  const double offset = std::min(a + b * texelSize, maxOffset);  // inf texel -> maxOffset
  return p + (dirFromLight / len) * offset;
}

glm::dvec3 directionFromLight(const glm::dvec4& light, const glm::dvec3& p) {
  if (light.w == 0.0) return -glm::normalize(glm::dvec3(light));
  const glm::dvec3 d = p - glm::dvec3(light) / light.w;
  const double len = glm::length(d);
  if (!(len > 0.0)) throw std::invalid_argument("point is at the light: no direction from it");
  return d / len;
}

glm::dmat4 constantDepthBiasMatrix(double bias) {
  if (!std::isfinite(bias)) throw std::invalid_argument("bias is not finite");
  glm::dmat4 m(1.0);
  m[3][2] = bias;
  return m;
}

double worldShiftOfDepthBias(const glm::dmat4& M, const glm::dvec3& p, const glm::dvec3& dir, double bias) {
  // d(depth)/ds along the ray by the quotient rule on (z/w)(p + s L).
  const glm::dvec4 h = M * glm::dvec4(p, 1.0);
  const glm::dvec4 dh = M * glm::dvec4(glm::normalize(dir), 0.0);
  const double slope = (dh.z * h.w - h.z * dh.w) / (h.w * h.w);
  if (slope == 0.0) return std::numeric_limits<double>::infinity();
  return std::abs(bias / slope);
}

}  // namespace shadowlab::psm

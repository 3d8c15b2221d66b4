#include "algorithms/moment_maps.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab::soft {
namespace {
double saturate(double v) { return std::clamp(v, 0.0, 1.0); }

// Peters and Klein's optimised quantisation (I3D 2015, their supplementary material): stored =
// kQuantise * b + (kOffset, 0, 0, 0); kDequantise is its inverse. GLM is column-major: each
// dmat4 argument group below is one column (the rows of the paper's row-vector form).
const glm::dmat4 kQuantise(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,       //
                           32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,  //
                           -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,   //
                           39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const glm::dmat4 kDequantise(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,   //
                             0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,  //
                             0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,  //
                             0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
constexpr double kOffset = 0.035955884801;
}  // namespace

double chebyshevUpperBound(double m1, double m2, double t, double minVariance) {
  if (t <= m1) return 1.0;
  const double variance = std::max(m2 - m1 * m1, minVariance);
  const double d = t - m1;
  return variance / (variance + d * d);
}

double reduceBleeding(double litShare, double amount) {
  const double a = std::clamp(amount, 0.0, 0.999);
  return saturate((litShare - a) / (1.0 - a));
}

glm::dvec4 evsmMoments(double t, double cPos, double cNeg) {
  const double w = 2.0 * t - 1.0;
  const double pos = std::exp(cPos * w), neg = -std::exp(-cNeg * w);
  return {pos, pos * pos, neg, neg * neg};
}

double evsmLitShare(const glm::dvec4& m, double t, double cPos, double cNeg, bool four, double minVariance) {
  const glm::dvec4 warped = evsmMoments(t, cPos, cNeg);
  // A variance floor of minVariance in t is (slope of the warp)^2 times it in warped units.
  const double slopePos = 2.0 * cPos * warped.x, slopeNeg = 2.0 * cNeg * warped.z;
  double lit = chebyshevUpperBound(m.x, m.y, warped.x, minVariance * slopePos * slopePos);
  if (four) lit = std::min(lit, chebyshevUpperBound(m.z, m.w, warped.z, minVariance * slopeNeg * slopeNeg));
  return lit;
}

glm::dvec4 msmMoments(double t) { return {t, t * t, t * t * t, t * t * t * t}; }

glm::dvec4 msmQuantise(const glm::dvec4& moments) { return kQuantise * moments + glm::dvec4(kOffset, 0, 0, 0); }

glm::dvec4 msmDequantise(const glm::dvec4& stored) { return kDequantise * (stored - glm::dvec4(kOffset, 0, 0, 0)); }

double msmLitShare(const glm::dvec4& moments, double t, double alpha) {
  const glm::dvec4 b = glm::mix(moments, glm::dvec4(0.5), alpha);
  // The Cholesky factorisation of the Hankel matrix B = ((1, b1, b2), (b1, b2, b3), (b2, b3, b4))
  // (only its non-trivial entries), then c with B c = (1, t, t^2)^T, by substitution.
  const double l32d22 = -b[0] * b[1] + b[2];
  const double d22 = -b[0] * b[0] + b[1];
  const double squaredVariance = -b[1] * b[1] + b[3];
  const double d33d22 = squaredVariance * d22 - l32d22 * l32d22;
  const double l32 = l32d22 / d22;
  glm::dvec3 c(1.0, t, t * t);
  c[1] -= b[0];
  c[2] -= b[1] + l32 * c[1];
  c[1] /= d22;
  c[2] *= d22 / d33d22;
  c[1] -= l32 * c[2];
  c[0] -= c[1] * b[0] + c[2] * b[1];
  // The other two support points: the roots of c0 + c1 z + c2 z^2.
  const double p = c[1] / c[2], q = c[0] / c[2];
  const double r = std::sqrt(std::max(p * p * 0.25 - q, 0.0));
  const double z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
  // Three Dirac deltas at t, z1 and z2 with these moments; the weight of those in front of t is
  // the shadow intensity (sw: which root pairs with t, and whether z1's weight counts whole).
  glm::dvec4 sw;
  if (z2 < t) sw = {z1, t, 1.0, 1.0};
  else if (z1 < t) sw = {t, z1, 0.0, 1.0};
  else sw = {0.0, 0.0, 0.0, 0.0};
  const double quotient = (sw[0] * z2 - b[0] * (sw[0] + z2) + b[1]) / ((z2 - sw[1]) * (t - z1));
  return 1.0 - saturate(sw[2] + sw[3] * quotient);
}

}  // namespace shadowlab::soft

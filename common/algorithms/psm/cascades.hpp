#pragma once
// Cascaded shadow maps' split distances: the "practical split scheme" (Zhang et al. 2006) mixing
// the logarithmic split (ideal for perspective aliasing) with the uniform one (lambda = 0):
//   z_i = lambda * zn (zf/zn)^(i/N) + (1 - lambda) * (zn + (zf - zn) i/N),  i = 0..N.
#include <vector>

namespace shadowlab::psm {

// N + 1 increasing distances from zn to zf (both exact). Throws std::invalid_argument for
// zn <= 0, zf <= zn, count < 1, lambda outside [0, 1] or non-finite values.
std::vector<double> cascadeSplits(double zNear, double zFar, int count, double lambda);
// The same into a caller's buffer (no allocation once warm).
void cascadeSplits(double zNear, double zFar, int count, double lambda, std::vector<double>& out);

}  // namespace shadowlab::psm

#pragma once
// Cascaded shadow maps' split distances: the "practical split scheme" (Zhang et al. 2006) mixing
// the logarithmic split (ideal for perspective aliasing) with the uniform one (lambda = 0):
//   z_i = lambda * zn (zf/zn)^(i/N) + (1 - lambda) * (zn + (zf - zn) i/N),  i = 0..N.
#include <span>
#include <vector>

namespace shadowlab::psm {

// N + 1 increasing distances from zn to zf (both exact). Throws std::invalid_argument for
// zn <= 0, zf <= zn, count < 1, lambda outside [0, 1] or non-finite values.
std::vector<double> cascadeSplits(double zNear, double zFar, int count, double lambda);
// The same into a caller's buffer (no allocation once warm).
void cascadeSplits(double zNear, double zFar, int count, double lambda, std::vector<double>& out);

// Which cascade shades a point at view depth `depth` (splits: N + 1 increasing distances), and how
// much of the next one is blended in: within the last `band` fraction of cascade i's depth range the
// weight of cascade i + 1 rises linearly from 0 to 1, so the switch leaves no seam (the last cascade
// has nobody to blend into). cascade = -1 outside [splits.front(), splits.back()]: no map covers it.
// shaders/10_showdown/shadow_cascades.frag mirrors it.
struct CascadeBlend {
  int cascade = -1;
  double nextWeight = 0.0;  // in [0, 1): the weight of cascade + 1
};
CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band);

// Each cascade's side at equal total texels: count maps of side s hold about totalSide^2 texels,
// s = floor(totalSide / sqrt(count)). Throws std::invalid_argument for count < 1 or totalSide < 1.
int cascadeSide(int totalSide, int count);

}  // namespace shadowlab::psm

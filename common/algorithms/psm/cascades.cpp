#include "algorithms/psm/cascades.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

void cascadeSplits(double zn, double zf, int count, double lambda, std::vector<double>& out) {
  if (!std::isfinite(zn) || zn <= 0.0) throw std::invalid_argument("zNear = " + std::to_string(zn) + " must be > 0");
  if (!std::isfinite(zf) || zf <= zn) throw std::invalid_argument("zFar = " + std::to_string(zf) + " must be > zNear");
  if (count < 1) throw std::invalid_argument("count = " + std::to_string(count) + " must be >= 1");
  if (!(lambda >= 0.0 && lambda <= 1.0))
    throw std::invalid_argument("lambda = " + std::to_string(lambda) + " must be in [0,1]");
  out.resize(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const double t = static_cast<double>(i) / count;
    const double logSplit = zn * std::pow(zf / zn, t);
    const double uniSplit = zn + (zf - zn) * t;
    out[i] = lambda * logSplit + (1.0 - lambda) * uniSplit;
  }
  out.front() = zn;  // exact ends, whatever pow rounds to
  out.back() = zf;
}

std::vector<double> cascadeSplits(double zn, double zf, int count, double lambda) {
  std::vector<double> out;
  cascadeSplits(zn, zf, count, lambda, out);
  return out;
}

}  // namespace shadowlab::psm

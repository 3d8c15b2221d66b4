#include "algorithms/psm/cascades.hpp"

#include <algorithm>
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

CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band) {
  CascadeBlend b;
  if (splits.size() < 2 || !(depth >= splits.front()) || depth > splits.back()) return b;
  const int last = int(splits.size()) - 2;
  b.cascade = 0;
  while (b.cascade < last && depth > splits[std::size_t(b.cascade) + 1]) ++b.cascade;
  if (b.cascade == last || band <= 0.0) return b;
  const double zFar = splits[std::size_t(b.cascade) + 1];
  const double width = band * (zFar - splits[std::size_t(b.cascade)]);
  const double start = zFar - width;
  if (depth > start) b.nextWeight = std::min((depth - start) / width, 1.0);
  return b;
}

int cascadeSide(int totalSide, int count) {
  if (count < 1) throw std::invalid_argument("cascade count = " + std::to_string(count) + " must be >= 1");
  if (totalSide < 1) throw std::invalid_argument("total side = " + std::to_string(totalSide) + " must be >= 1");
  return std::max(1, int(std::floor(double(totalSide) / std::sqrt(double(count)) + 1e-9)));
}

}  // namespace shadowlab::psm

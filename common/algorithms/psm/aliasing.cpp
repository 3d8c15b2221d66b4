#include "algorithms/psm/aliasing.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

namespace {
double checkedN(Parameterisation p, double z, double zn, double zf, double n) {
  if (!std::isfinite(zn) || zn <= 0.0) throw std::invalid_argument("zNear = " + std::to_string(zn) + " must be > 0");
  if (!std::isfinite(zf) || zf <= zn) throw std::invalid_argument("zFar = " + std::to_string(zf) + " must be > zNear");
  if (!(z >= zn && z <= zf)) throw std::invalid_argument("z = " + std::to_string(z) + " is outside [zNear, zFar]");
  if (p != Parameterisation::Lispsm) return 0.0;
  if (!(n >= 0.0) || !std::isfinite(n)) throw std::invalid_argument("lispsmN = " + std::to_string(n) + " must be >= 0");
  return n == 0.0 ? zn + std::sqrt(zn * zf) : n;
}
}  // namespace

double perspectiveAliasing(Parameterisation p, double z, double zn, double zf, double lispsmN) {
  const double n = checkedN(p, z, zn, zf, lispsmN);
  switch (p) {
    case Parameterisation::Uniform: return (zf - zn) / z;
    case Parameterisation::Psm: return z * (zf - zn) / (zn * zf);
    case Parameterisation::Lispsm: {
      const double zp = z - zn + n, fp = zf - zn + n;
      return zp * zp * (1.0 / n - 1.0 / fp) / z;
    }
    case Parameterisation::Logarithmic: return std::log(zf / zn);
  }
  return 0.0;
}

double shadowMapCoordinate(Parameterisation p, double z, double zn, double zf, double lispsmN) {
  const double n = checkedN(p, z, zn, zf, lispsmN);
  switch (p) {
    case Parameterisation::Uniform: return (z - zn) / (zf - zn);
    case Parameterisation::Psm: return (1.0 / zn - 1.0 / z) / (1.0 / zn - 1.0 / zf);
    case Parameterisation::Lispsm: {
      const double zp = z - zn + n, fp = zf - zn + n;
      return (1.0 / n - 1.0 / zp) / (1.0 / n - 1.0 / fp);
    }
    case Parameterisation::Logarithmic: return std::log(z / zn) / std::log(zf / zn);
  }
  return 0.0;
}

}  // namespace shadowlab::psm

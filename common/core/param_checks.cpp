#include "core/param_checks.hpp"

#include <sstream>

namespace shadowlab {
namespace {

std::string number(float v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

void addLightChecks(ParamRegistry& r, const std::string& prefix, const Light& l) {
  const std::string direction = prefix + "direction", attenuation = prefix + "attenuation";
  r.addCheck({direction}, [&l, direction](const ParamRegistry& r) {
    if (glm::length(glm::dvec3(l.direction)) >= kMinDirectionLength) return std::string();
    return direction + " = " + r.get(direction) + " is not a direction: it needs a length of at least " +
           number(kMinDirectionLength) + " (the light would shine nowhere)";
  });
  r.addCheck({attenuation}, [&l, attenuation](const ParamRegistry& r) {
    const glm::vec3 c = l.attenuation;  // each in [0, 10]: only all zero divides by zero
    if (c.x + c.y + c.z >= 1e-6f) return std::string();
    return attenuation + " = " + r.get(attenuation) +
           " divides by zero: f_att = 1 / (c0 + c1 d + c2 d^2) needs a coefficient above 0";
  });
}

void addCameraChecks(ParamRegistry& r, const OrbitCamera& c) {
  r.addCheck({"camera.near", "camera.far"}, [&c](const ParamRegistry& r) {
    const std::string planes = "camera.near = " + r.get("camera.near") + ", camera.far = " + r.get("camera.far");
    if (!(c.nearZ < c.farZ)) return planes + ": the near plane must lie before the far plane";
    if (c.farZ / c.nearZ > kMaxDepthRatio)  // in float, as the projection computes it
      return planes + ": far / near is " + number(c.farZ / c.nearZ) + ", at most " + number(kMaxDepthRatio) +
             " (beyond it the view volume degenerates in float)";
    return std::string();
  });
}

}  // namespace shadowlab

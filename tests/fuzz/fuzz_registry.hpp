#pragma once
// A registry with every parameter kind and the framework's checks (light direction, attenuation,
// camera planes), for the preset and --set targets.
#include <tuple>

#include "core/param_checks.hpp"
#include "core/params.hpp"

namespace shadowlab::fuzz {

enum class Mode { Lit, Normals, Depth };

struct Registry {
  float ambient = 0.1f;
  int samples = 4;
  bool shadows = true;
  Mode mode = Mode::Lit;
  glm::vec3 color{1, 0.5f, 0};
  Light light;
  OrbitCamera camera;
  ParamRegistry reg;
  Registry() {
    reg.add("ambient", &ambient, 0, 1, "k_a");
    reg.add("samples", &samples, 1, 64, "taps");
    reg.add("shadows", &shadows, "V_i");
    reg.addChoice("mode", &mode, {"lit", "normals", "depth"}, "view");
    reg.addColor("color", &color, "colour");
    reg.add("light0.direction", &light.direction, -1, 1, "direction");
    reg.add("light0.attenuation", &light.attenuation, 0, 10, "c0 c1 c2");
    addLightChecks(reg, "light0.", light);
    reg.add("camera.near", &camera.nearZ, 1e-4f, 100.0f, "near");
    reg.add("camera.far", &camera.farZ, 0.1f, 1e7f, "far");
    addCameraChecks(reg, camera);
  }
  // Every value, exactly (cheaper than snapshot(), which formats text).
  auto values() const {
    return std::make_tuple(ambient, samples, shadows, mode, color, light.direction, light.attenuation, camera.nearZ,
                           camera.farZ);
  }
  // After anything the registry accepted or refused, its values pass every check.
  void checkConsistent() const {
    try {
      reg.validate();
    } catch (const ParamError&) { FUZZ_CHECK(!"the registry holds values its checks refuse"); }
  }
};

}  // namespace shadowlab::fuzz

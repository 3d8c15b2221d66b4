#pragma once
// Parameter sets the registry's tests and fuzz targets share: one field of every kind, and the
// parameters the framework's checks read, with declareLight's and declareCamera's ranges.
// Header-only: the fuzz build (tests/fuzz) links no test support library.
#include "core/param_checks.hpp"
#include "core/params.hpp"

namespace shadowlab::test {

enum class Mode { Lit, Normals, Depth };

struct SampleParams {
  float ambient = 0.1f;
  int samples = 4;
  bool shadows = true;
  Mode mode = Mode::Lit;
  glm::vec3 color{1, 0.5f, 0};
  void declare(ParamRegistry& r) {
    r.add("ambient", &ambient, 0, 1, "k_a");
    r.add("samples", &samples, 1, 64, "PCF taps");
    r.add("shadows", &shadows, "V_i on/off");
    r.addChoice("mode", &mode, {"lit", "normals", "depth"}, "what to show");
    r.addColor("color", &color, "light colour");
  }
};

struct SampleRig {
  Light light;
  OrbitCamera camera;
  void declare(ParamRegistry& r) {
    r.add("light0.direction", &light.direction, -1, 1, "spot axis or sun travel");
    r.add("light0.attenuation", &light.attenuation, 0, 10, "c0 c1 c2");
    addLightChecks(r, "light0.", light);
    r.add("camera.near", &camera.nearZ, 1e-4f, 100.0f, "near plane");
    r.add("camera.far", &camera.farZ, 0.1f, 1e7f, "far plane");
    addCameraChecks(r, camera);
  }
};

}  // namespace shadowlab::test

#pragma once
// A registry with every parameter kind and the framework's checks (light direction, attenuation,
// camera planes), for the preset and --set targets.
#include <tuple>

#include "sample_params.hpp"

namespace shadowlab::fuzz {

struct Registry {
  test::SampleParams p;
  test::SampleRig rig;
  ParamRegistry reg;
  Registry() {
    p.declare(reg);
    rig.declare(reg);
  }
  // Every value, exactly (cheaper than snapshot(), which formats text).
  auto values() const {
    return std::make_tuple(p.ambient, p.samples, p.shadows, p.mode, p.color, rig.light.direction, rig.light.attenuation,
                           rig.camera.nearZ, rig.camera.farZ);
  }
  // After anything the registry accepted or refused, its values pass every check.
  void checkConsistent() const {
    try {
      reg.validate();
    } catch (const ParamError&) { FUZZ_CHECK(!"the registry holds values its checks refuse"); }
  }
};

}  // namespace shadowlab::fuzz

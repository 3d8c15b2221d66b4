// The framework's checks on the light rig and the camera (core/param_checks): values that each
// pass their range but together leave nothing to render are refused with one line naming the
// parameter, and the last good value stays.
#include <doctest/doctest.h>

#include <string>

#include "algorithms/shadow_math.hpp"
#include "core/param_checks.hpp"
#include "sample_params.hpp"

using namespace shadowlab;

namespace {
struct Rig : test::SampleRig {
  ParamRegistry reg;
  Rig() { declare(reg); }
  std::string error(const std::string& assignment) {
    try {
      reg.assign(assignment);
    } catch (const ParamError& e) { return e.what(); }
    return "no error";
  }
};
}  // namespace

TEST_CASE("param checks: a light direction needs a length, the last good one stays") {
  Rig r;
  CHECK_NOTHROW(r.reg.validate());
  CHECK(r.error("light0.direction=0 0 0") ==
        "light0.direction = 0 0 0 is not a direction: it needs a length of at least 1e-06 (the light would shine "
        "nowhere)");
  CHECK(r.light.direction == glm::vec3(0, -1, 0));
  // 1e-45 is a float (a denormal) inside the range; normalising it gives NaN.
  CHECK(r.error("light0.direction=1e-45 0 0").rfind("light0.direction = 1.4013e-45 0 0 is not a direction", 0) == 0);
  CHECK(r.light.direction == glm::vec3(0, -1, 0));
  CHECK(r.error("light0.direction=1e-6 0 0") == "no error");  // short, but it normalises
  CHECK(r.error("light0.direction=0.3 -0.2 0") == "no error");
}

TEST_CASE("param checks: attenuation 0 0 0 divides by zero, any coefficient above 0 is fine") {
  Rig r;
  CHECK(r.error("light0.attenuation=0 0 0") ==
        "light0.attenuation = 0 0 0 divides by zero: f_att = 1 / (c0 + c1 d + c2 d^2) needs a coefficient above 0");
  CHECK(r.light.attenuation == glm::vec3(1, 0, 0.01f));
  CHECK(r.error("light0.attenuation=0 0 1") == "no error");  // the inverse square law
  CHECK(r.error("light0.attenuation=0 0.5 0") == "no error");
}

TEST_CASE("param checks: camera.near must lie before camera.far, within a ratio float depth resolves") {
  Rig r;
  CHECK(r.error("camera.near=5") == "no error");
  CHECK(r.error("camera.far=2") == "camera.near = 5, camera.far = 2: the near plane must lie before the far plane");
  CHECK(r.camera.farZ == 200.0f);
  CHECK(r.error("camera.near=100") == "no error");  // still before it
  CHECK(r.error("camera.far=100") ==
        "camera.near = 100, camera.far = 100: the near plane must lie before the far plane");
  CHECK(r.camera.farZ == 200.0f);
  // The reproducer: each in range, together a ratio of 1e11.
  CHECK(r.error("camera.near=1e-4") ==
        "camera.near = 0.0001, camera.far = 200: far / near is 2e+06, at most 1e+06 (beyond it the view volume "
        "degenerates in float)");
  CHECK(r.camera.nearZ == 100.0f);
  CHECK(r.error("camera.far=1e7") == "no error");  // 1e5 with near 100
  std::string both;
  try {
    r.reg.assignAll({"camera.near=1e-4", "camera.far=1e7"});
  } catch (const ParamError& e) { both = e.what(); }
  CHECK(both ==
        "camera.near = 0.0001, camera.far = 1e+07: far / near is 1e+11, at most 1e+06 (beyond it the view volume "
        "degenerates in float)");
  CHECK(r.camera.nearZ == 100.0f);
  CHECK(r.camera.farZ == 1e7f);
  r.reg.assignAll({"camera.far=100", "camera.near=1e-4"});  // exactly the limit, and in one change
  CHECK(r.camera.farZ == 100.0f);
  CHECK(r.camera.nearZ == 1e-4f);
}

TEST_CASE("param checks: at the limit a float view volume still has six faces (shadow fitting needs them)") {
  // Lesson 03 fits shadow cameras to the viewer through volumeFromViewProj; at far / near = 1e11
  // it threw "degenerate face 0" at render time. At the limit, over the camera's ranges near the
  // origin, it holds (probed: the first failures come at 5e6).
  OrbitCamera c;
  for (float nearZ : {1e-4f, 1e-3f, 0.1f, 1.0f, 10.0f})
    for (float fov : {0.1f, 0.873f, 3.0f})
      for (float pitch : {0.0f, 1.5f})
        for (float distance : {1.0f, 12.0f, 30.0f}) {
          c.nearZ = nearZ;
          c.farZ = nearZ * kMaxDepthRatio;
          c.fovY = fov;
          c.pitch = pitch;
          c.distance = distance;
          INFO("near " << nearZ << " fov " << fov << " pitch " << pitch << " distance " << distance);
          CHECK_NOTHROW(shadow::volumeFromViewProj(c.projection(16.0f / 9.0f) * c.view()));
        }
  c.nearZ = 1e-4f;
  c.farZ = 1e7f;
  CHECK_THROWS_AS(shadow::volumeFromViewProj(c.projection(16.0f / 9.0f) * c.view()), std::invalid_argument);
}

// Camera and light path files and --replay FILE@T (measure/paths): a path whose every key and
// sample a camera can look along, or std::runtime_error; a spec, or std::invalid_argument.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/camera.hpp"
#include "fuzz_support.hpp"
#include "measure/paths.hpp"

using namespace shadowlab;

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = fuzz::text(data, size);
  try {
    const measure::ReplaySpec spec = measure::parseReplaySpec(input.substr(0, input.find('\n')));
    FUZZ_CHECK(spec.holdAt == -1.0 || (spec.holdAt >= 0.0 && std::isfinite(spec.holdAt)));
    FUZZ_CHECK(spec.from == -1.0 || (spec.from >= 0.0 && spec.to > spec.from && std::isfinite(spec.to)));
    FUZZ_CHECK(std::isfinite(spec.timeAt(2.0, 3, 7, 0.5)));
  } catch (const std::invalid_argument&) {}
  std::istringstream in(input);
  try {
    const measure::CameraLightPath path = measure::CameraLightPath::read(in, "fuzz.path");
    if (path.empty()) return 0;
    OrbitCamera camera;
    for (const measure::PathKey& k : path.resample(7)) {
      FUZZ_CHECK(finite(k.cameraPosition) && finite(k.cameraTarget) && finite(k.lightPosition));
      FUZZ_CHECK(std::abs(glm::length(k.lightDirection) - 1.0f) < 1e-3f);
      camera.lookFrom(k.cameraPosition, k.cameraTarget);  // threw out of every lesson (exit 134)
    }
  } catch (const std::runtime_error&) {}
  return 0;
}

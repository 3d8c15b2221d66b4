#include "many_lights.hpp"

#include <algorithm>

#include "algorithms/soft_shadows.hpp"

namespace shadowlab::tech {

void ManyLights::declare(ParamRegistry& r, const std::string& n) {
  r.add(n + "samples", &p_.samples, 1, SoftMaps::kMaxSamples, "point lights on the sphere, one map each (1: hard)");
  r.addChoice(n + "layout", &p_.layout, {"ball", "disk"},
              "samples whose shadow is a uniform disk from any direction, or a disk across the light's axis");
  maps_.declare(r, n);
  maps_.checkBudget(r, n, &p_.samples);
}

std::vector<glm::vec3> ManyLights::samplesFor(int n, SampleLayout layout) {
  n = std::clamp(n, 1, SoftMaps::kMaxSamples);
  if (layout == SampleLayout::Ball) return soft::isotropicBallSamples(n);
  std::vector<glm::vec3> out;
  for (const glm::vec2& d : soft::stratifiedDiskSamples(n)) out.push_back(glm::vec3(d, 0.0f));
  return out;
}

std::vector<std::string> ManyLights::shaderDefines() const {
  return {"SOFT_SAMPLES " + std::to_string(std::clamp(p_.samples, 1, SoftMaps::kMaxSamples))};
}

void ManyLights::render(const ShadowContext& c) {
  stats_ = {};
  maps_.render(c, samplesFor(p_.samples, p_.layout), stats_);
  stats_.extra.push_back({"point lights", std::to_string(maps_.samples().size()) + " per light, " +
                                              std::to_string(maps_.mapSize()) + "^2 each"});
}

}  // namespace shadowlab::tech

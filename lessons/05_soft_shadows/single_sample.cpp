#include "single_sample.hpp"

#include "pcss.hpp"

namespace shadowlab::tech {

SingleSampleSoft::SingleSampleSoft(Kind kind, SingleSampleParams defaults)
    : kind_(kind), p_(defaults), maps_(kind == Kind::Parker ? "parker" : "haines", defaults.maps) {}

int SingleSampleSoft::searchCount() const { return p_.searchTaps; }

void SingleSampleSoft::declare(ParamRegistry& r, const std::string& n) {
  r.addNumberChoice(n + "search_taps", &p_.searchTaps, PcssShadows::kTapCounts, "taps looking for the nearest blocker");
  r.add(n + "max_search", &p_.maxSearch, 0.005f, 0.5f, "cap of the search region (uv)");
  r.addChoice(n + "profile", &p_.profile, {"exact", "linear"},
              "shade the penumbra with A_frac or its linear approximation (1 + a/R) / 2");
  if (kind_ == Kind::Haines) {
    r.add(n + "plane", &p_.planeHeight, -10, 10, "height of the receiving plane (the only receiver with a penumbra)");
    r.add(n + "plane_tolerance", &p_.planeTolerance, 0, 1, "how far from the plane a receiver still counts");
  }
  maps_.declare(r, n);
}

std::vector<std::string> SingleSampleSoft::shaderDefines() const {
  std::vector<std::string> d = {"SEARCH_TAPS " + std::to_string(searchCount())};
  if (kind_ == Kind::Haines) d.push_back("HAINES");
  if (p_.profile == soft::Profile::Linear) d.push_back("LINEAR_PROFILE");
  return d;
}

void SingleSampleSoft::render(const ShadowContext& c) {
  stats_ = {};
  maps_.render(c, {glm::vec3(0.0f)}, stats_);
  stats_.extra.push_back({"taps", std::to_string(searchCount()) + " blocker search"});
}

void SingleSampleSoft::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  setTaps(lit, "uSearchTaps", soft::poissonDisk(searchCount(), 13));
  lit.set("uMaxSearch", p_.maxSearch);
  lit.set("uPlaneHeight", p_.planeHeight);
  lit.set("uPlaneTolerance", p_.planeTolerance);
  const auto& lights = maps_.lights();
  for (std::size_t i = 0; i < lights.size(); ++i)
    if (lights[i].on)
      lit.set(("uSoftViewInverse[" + std::to_string(i) + "]").c_str(), glm::inverse(lights[i].centre.view));
}

}  // namespace shadowlab::tech

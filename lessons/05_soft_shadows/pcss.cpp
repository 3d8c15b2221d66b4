#include "pcss.hpp"

#include "algorithms/soft_shadows.hpp"
#include "gl/caps.hpp"

namespace shadowlab::tech {

PcssShadows::PcssShadows(bool adaptive, PcssParams defaults)
    : adaptive_(adaptive), p_(defaults), maps_(adaptive ? "pcss" : "pcf", defaults.maps) {}

int PcssShadows::searchCount() const { return p_.searchTaps; }
int PcssShadows::filterCount() const { return p_.filterTaps; }
bool PcssShadows::quadSearchOn() const { return adaptive_ && p_.quadSearch && gl::caps().derivativeControl; }

void PcssShadows::declare(ParamRegistry& r, const std::string& n) {
  r.addNumberChoice(n + "filter_taps", &p_.filterTaps, kTapCounts, "Poisson taps of the filter, rotated per pixel");
  if (adaptive_) {
    r.addNumberChoice(n + "search_taps", &p_.searchTaps, kTapCounts, "Poisson taps of the blocker search");
    r.add(n + "max_search", &p_.maxSearch, 0.005f, 0.5f, "cap of the blocker search region (uv)");
    r.add(n + "min_filter", &p_.minFilter, 0, 8, "smallest filter radius (texels)");
    r.add(n + "quad_search", &p_.quadSearch,
          "a 2x2 pixel quad shares one blocker search, each pixel reading a quarter of its taps "
          "(GL_ARB_derivative_control)");
  } else {
    r.add(n + "radius", &p_.fixedRadius, 0, 32, "the fixed kernel's radius (texels): one penumbra for all");
  }
  maps_.declare(r, n);
}

std::vector<std::string> PcssShadows::shaderDefines() const {
  // PCSS's filter count is a uniform (bindVisibility), PCF's compiles in: see shadow_pcss.frag.
  // The quad search compiles each pixel's quarter of the taps in: the exercise's loop is unchanged.
  const bool quad = quadSearchOn();
  std::vector<std::string> d = {"SEARCH_TAPS " + std::to_string(quad ? searchCount() / 4 : searchCount())};
  if (quad) d.push_back("QUAD_SEARCH 1");
  d.push_back(adaptive_ ? "PCSS" : "FILTER_TAPS " + std::to_string(filterCount()));
  if (adaptive_ && student.glslSearch) d.push_back("SHADOWLAB_STUDENT_PCSS");
  return d;
}

void PcssShadows::render(const ShadowContext& c) {
  stats_ = {};
  maps_.render(c, {glm::vec3(0.0f)}, stats_);
  const std::string filter = std::to_string(filterCount()) + " filter";
  std::string search = std::to_string(searchCount()) + " search";
  if (quadSearchOn()) search += " (" + std::to_string(searchCount() / 4) + " a pixel, shared by its quad)";
  else if (adaptive_ && p_.quadSearch)
    search += gl::caps().gles ? " (quad search off: WebGL2 has no fine derivatives)"
                              : " (quad search off: no GL_ARB_derivative_control)";
  stats_.extra.push_back({"taps", adaptive_ ? search + " + " + filter : filter});
}

void PcssShadows::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  // Different seeds: the search and the filter should not sample the same directions.
  setTaps(lit, "uSearchTaps",
          quadSearchOn() ? soft::quarterTurnDisk(searchCount(), 11) : soft::poissonDisk(searchCount(), 11));
  setTaps(lit, "uFilterTaps", soft::poissonDisk(filterCount(), 12));
  if (adaptive_) lit.set("uFilterCount", filterCount());
  lit.set("uFixedRadius", p_.fixedRadius);
  lit.set("uMaxSearch", p_.maxSearch);
  lit.set("uMinFilter", p_.minFilter);
}

}  // namespace shadowlab::tech

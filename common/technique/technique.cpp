#include "technique/technique.hpp"

namespace shadowlab::tech {

std::vector<Counter> ShadowStats::counters() const {
  std::vector<Counter> out = {{"shadow triangles", std::to_string(triangles)},
                              {"shadow texels", std::to_string(texels)}};
  if (culls) {
    out.push_back({"culled casters", std::to_string(culledCasters)});
    out.push_back({"cube faces skipped", std::to_string(skippedFaces)});
  }
  if (reusedMaps > 0) out.push_back({"maps reused", std::to_string(reusedMaps)});
  if (bytes > 0) out.push_back({"shadow memory", std::to_string(bytes / 1024) + " KiB"});
  out.insert(out.end(), extra.begin(), extra.end());
  return out;
}

}  // namespace shadowlab::tech

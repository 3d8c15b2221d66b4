#include "technique/technique.hpp"

namespace shadowlab::tech {

std::string drawnFigure(std::uint64_t now, std::uint64_t kept) {
  if (kept == 0) return std::to_string(now);
  if (now == 0) return std::to_string(kept) + " (kept, as drawn)";
  return std::to_string(now + kept) + " (" + std::to_string(kept) + " of them kept)";
}

std::vector<Counter> ShadowStats::counters() const {
  std::vector<Counter> out = {{"shadow triangles", drawnFigure(triangles, kept.triangles)},
                              {"shadow texels", drawnFigure(texels, kept.texels)}};
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

#pragma once
// Random source maps for lesson 07's cases (public and hidden), swept with eps0 = 0.01.
#include <random>
#include <vector>

#include "exercises.hpp"

namespace shadowlab::test {

// An n x n map: `flat` on the texels whose (x / cell.x + y / cell.y) % cell.z == 0, elsewhere
// `rest` with rare bumps of up to 0.3; its merge pyramid to `levels` on window depth.
inline std::vector<hybrid::MergeGrid> randomSweep(std::mt19937_64& rng, int n, int levels, glm::ivec3 cell, float flat,
                                                  float rest) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> d(std::size_t(n) * std::size_t(n));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float bump = u(rng), rare = u(rng);
      d[std::size_t(y) * n + x] = (x / cell.x + y / cell.y) % cell.z == 0 ? flat : rest + 0.3f * bump * (rare < 0.05f);
    }
  hybrid::MergeRule r;
  r.eps0 = 0.01f;
  return hybrid::mergeSweep(shadow::DepthMap(n, n, d), r, levels);
}

// A grid of 2..31 texels a side: 0.6 to 0.65, a tenth of them kInternal (kept below); and an eps0
// below 0.05, so that both kinds of block occur.
struct RandomLevel {
  hybrid::MergeGrid children;
  float eps0 = 0.0f;
};
inline RandomLevel randomLevel(std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int n = 2 + int(u(rng) * 30.0f);
  RandomLevel l{{n, std::vector<float>(std::size_t(n) * std::size_t(n))}, 0.0f};
  for (float& x : l.children.value) x = u(rng) < 0.1f ? hybrid::kInternal : 0.6f + 0.05f * u(rng);
  l.eps0 = 0.05f * u(rng);
  return l;
}

}  // namespace shadowlab::test

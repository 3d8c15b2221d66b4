#pragma once
// Light-mesh grids for lesson 05's cases (public and hidden).
#include "exercises.hpp"

namespace shadowlab::test {

// A 5 x 3 x 4 grid, 1 m apart from the origin, with the visibility f(x, y, z) at its nodes.
template <class F>
soft::LightGrid lightGrid(F f) {
  soft::LightGrid g;
  g.origin = {0, 0, 0};
  g.step = glm::vec3(1.0f);
  g.nodes = {5, 3, 4};
  g.visibility.resize(g.count());
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) g.visibility[g.index({x, y, z})] = f(float(x), float(y), float(z));
  return g;
}

}  // namespace shadowlab::test

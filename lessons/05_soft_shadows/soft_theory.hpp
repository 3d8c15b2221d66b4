#pragma once
// The soft-shadow theory drawn live over a lesson's frame (lesson 05): the lecture's predicted
// penumbra of one caster edge (the centre line and the inner and outer edges, r = d / (n.L) * R / D
// either side: soft::penumbraAlongEdge) as lines, and A_frac against its linear approximation as an
// ImGui plot with the largest difference printed. The functions plotted are the caller's, so a
// lesson shows its student's code there (impl=student).
#include <functional>
#include <string>
#include <vector>

#include "algorithms/soft_shadows.hpp"
#include "app/debug_draw.hpp"

namespace shadowlab::tech {

// The lines of a predicted penumbra: the caster edge (white), its shadow's centre line (yellow), the
// inner edge toward the umbra (red) and the outer edge (cyan), joined by ticks across every fourth sample.
std::vector<DebugDraw::Line> penumbraLines(const glm::vec3& edgeA, const glm::vec3& edgeB,
                                           const std::vector<soft::PenumbraEdgeSample>& samples);

using FractionFn = std::function<float(float)>;
// The largest |exact - linear| over [-1, 1] (1001 points) and where.
struct PlotFigures {
  float maxDifference = 0, at = 0;
};
PlotFigures compareFractions(const FractionFn& exact, const FractionFn& linear);
// An ImGui window "A_frac": both curves over a/R in [-1, 1], the difference, the figures.
void visibleFractionPlot(const FractionFn& exact, const FractionFn& linear);

}  // namespace shadowlab::tech

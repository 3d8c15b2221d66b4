#pragma once
// Lesson 10 exercises: the maths of cascaded shadow maps (technique=csm), GL-free. Write them in
// exercises.cpp; grade with
//   make grade LESSON=10   (it builds what changed first)
// and see yours live with  lesson_10_showdown --set impl=student  (technique=csm runs your split
// scheme, 10.1, and your texel snapping, 10.2; 10.3 is what shaders/10_showdown/shadow_cascades.frag does
// for every pixel, written here in C++).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/cascades.hpp"
#include "algorithms/shadow_math.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex10 {

// EXERCISE 10.1: the practical split scheme ([Zhang2006]). Cut the view's depth range [zNear, zFar]
// into `count` cascades: return the count + 1 distances z_0 = zNear < z_1 < ... < z_count = zFar,
//   z_i = lambda * zNear (zFar / zNear)^(i / count) + (1 - lambda) * (zNear + (zFar - zNear) i / count)
// (lambda = 1: the logarithmic split, the same perspective aliasing in every cascade; lambda = 0: the
// uniform split, which wastes texels far away). Compute in double, i / count as a double, and set
// the two ends to exactly zNear and zFar whatever pow rounds to. 0 < zNear < zFar, count >= 1,
// 0 <= lambda <= 1.
std::vector<double> practicalSplits(double zNear, double zFar, int count, double lambda);

// EXERCISE 10.2: texel snapping of one cascade's orthographic box. In the light's view space the
// fitted box has its centre and half extents (x, y). Make it stable while the camera moves:
//   h     = max(half.x, half.y, 1e-3) * (1 + 2 / mapSize)    square, with a texel of room each side
//   step  = 2^ceil(log2 h) / 4;   h = ceil(h / step) * step  the size moves only in steps
//   texel = 2 h / mapSize;  centre = round(centre / texel) * texel   the centre on the texel grid
// Compute in float, in that order (glm::round, std::exp2, std::log2, std::ceil). Return the snapped
// centre and half side h (shadow::TexelSnap).
shadow::TexelSnap snapToTexels(const glm::vec2& centre, const glm::vec2& half, int mapSize);

// EXERCISE 10.3: the cascade that shades a point at view depth `depth` (splits: count + 1
// increasing distances, as 10.1 returns) and the blend band. The cascade is the first i with depth
// <= splits[i + 1] (a depth exactly on a split belongs to the nearer cascade). Within the last
// `band` fraction of cascade i's depth range the next cascade is blended in: with
//   width = band * (splits[i + 1] - splits[i]),  start = splits[i + 1] - width,
// nextWeight = min((depth - start) / width, 1) when depth > start, else 0. The last cascade and
// band <= 0 blend nothing (weight 0). Outside [splits.front(), splits.back()] (or fewer than 2
// splits) no map covers the point: return cascade -1, weight 0.
shadow::CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band);

}  // namespace shadowlab::ex10

#pragma once
// Lesson 07 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=07   (it builds what changed first)
// and see yours live with  lesson_07_hybrid_maps --set impl=student
// (your sweep, 07.1 and 07.2, then builds the sun's map on the CPU: read back, swept, uploaded).
#include <array>

#include "algorithms/hybrid_map.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex07 {

// EXERCISE 07.1: the paper's merge criterion on one 2x2 block ([LiHua2016] eq. 1). d holds the
// four depths D1..D4. Their mean is m = ((D1 + D2) + (D3 + D4)) * 0.25 (in that order, in float).
// The block merges when |m - Dn| <= eps0 * Dn for every n (written as a product, not a quotient:
// no division by a depth of 0). A negative depth marks a child that did not merge at the level
// below (hybrid::kInternal): then the block never merges. Return {merged, m} (m may be anything
// when not merged).
hybrid::BlockMerge mergeBlock(const std::array<float, 4>& d, float eps0);

// EXERCISE 07.2: one level of the sweep. `children` is a size x size grid (row-major, row 0 first)
// of depths, kInternal where a texel did not merge. Return the next level: (size + 1) / 2 a side,
// texel (x, y) from the block (2x, 2y), (2x+1, 2y), (2x, 2y+1), (2x+1, 2y+1) in that order through
// mergeBlock: its mean when merged, else kInternal. A block cut by the grid's border (2x + 1 or
// 2y + 1 outside) is kInternal.
hybrid::MergeGrid sweepLevel(const hybrid::MergeGrid& children, float eps0);

// EXERCISE 07.3: the index descent. For source texel (sx, sy) (0 <= sx, sy < map.sourceSize) read
// the root word at (sx >> levels, sy >> levels); while it is a pointer (hybrid::isPointer) and
// level > 0: go one level down (level - 1), the record hybrid::recordIndex(word) and its child
// ((sx >> level) & 1) + 2 * ((sy >> level) & 1). Return the leaf's depth (hybrid::leafDepth), the
// level it was stored at and the pointers followed.
hybrid::Descent descend(const hybrid::HybridMap& map, int sx, int sy);

// EXERCISE 07.4: why the paper's criterion merges too much behind a perspective light. Window depth
// d in [0,1] of a perspective frustum (near n, far f) is hyperbolic in distance; undo it:
//   z = 2 n f / ((f + n) - (2 d - 1)(f - n))      (z = n at d = 0, z = f at d = 1)
float linearDepth(float windowDepth, float nearZ, float farZ);

}  // namespace shadowlab::ex07

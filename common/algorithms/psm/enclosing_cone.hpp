#pragma once
// The smallest cone from an apex holding a set of directions ([Kozlov2004] §4.1, after Gaertner
// 1999). For unit vectors u_i inside an open hemisphere, the cone {u : dot(axis, u) >= cos(angle)}
// of least angle is the sphere cut by the smallest ball enclosing the points u_i: the ball's
// boundary meets the unit sphere in the cone's circle, whose centre is the ball's centre c, so
// axis = c / |c|. The ball comes from Welzl's move-to-front recursion, written as nested loops
// (expected linear time over a random order).
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab::psm {

struct Cone {
  glm::dvec3 axis{0.0, 0.0, -1.0};  // unit
  double halfAngle = 0.0;           // radians; every input u has angle(axis, u) <= halfAngle
  bool valid = false;               // false: empty input, or no cone narrower than a hemisphere
};

// Smallest cone holding every direction (need not be unit; zero or non-finite ones throw
// std::invalid_argument naming the index). Deterministic (a fixed seed); the directions are not
// changed, and a per-thread buffer for the core set is reused. valid is false when the directions
// do not fit in an open hemisphere (half-angle >= pi/2 - 1e-9).
Cone smallestEnclosingCone(std::span<const glm::dvec3> directions);

// The same cone from an apex over points (the directions p - apex, no copy of them made), with
// the least and greatest distance along its axis, dot(p - apex, axis), measured on the way (the
// light camera's depth range). core: scratch for the core set (kept warm, no allocation then).
// bad < points.size(): that point is at the apex or not finite, and nothing else is meaningful.
struct ConeFit {
  Cone cone;
  double minAlong = std::numeric_limits<double>::max(), maxAlong = -std::numeric_limits<double>::max();
  std::size_t bad = std::numeric_limits<std::size_t>::max();
};
ConeFit enclosingConeFrom(const glm::dvec3& apex, std::span<const glm::dvec3> points, std::vector<glm::dvec3>& core);

// The same optimum by exhaustive search over every cone through 1, 2 or 3 of the directions:
// O(n^4), for tests and for students checking their own on small sets.
Cone smallestEnclosingConeBruteForce(std::span<const glm::dvec3> directions);

}  // namespace shadowlab::psm

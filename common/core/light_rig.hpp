#pragma once
// The course's recurring lights, defined once for the lessons that share them.
#include <glm/glm.hpp>

#include "core/light.hpp"

namespace shadowlab {

// A sun travelling along `direction` (normalised here), warm white at 0.9.
Light courseSun(const glm::vec3& direction);
// A warm point light at `position` (intensity 3, attenuation 1 + 0.05 d + 0.02 d^2), off: the second
// light of lessons 08 and 09, for a student to switch on.
Light courseLamp(const glm::vec3& position);
// Lesson 05's spherical light: a spot of radius 0.5 m 7 m over the showcase, its cone holding every
// shape and its shadow, placed across the plane of the box's edge 11 (tests/unit/test_soft_truth).
Light showcaseSphereSpot();
// Lesson 05's second, smaller sphere (blue, radius 0.3 m, off): every soft technique serves several.
Light secondSphereSpot();

}  // namespace shadowlab

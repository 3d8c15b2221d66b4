#pragma once
// The course's lights, defined once: every lesson's Params holds its lights as a few of these
// (lesson 03: courseSun, courseLamp, citySpot) and declares them as light0, light1, ... with
// declareLights (app/lesson.hpp), so a light's parameters look the same in every lesson.
#include <array>

#include <glm/glm.hpp>

#include "core/light.hpp"

namespace shadowlab {

// The lit scene's rig (lessons 01 and 04): a sun, a warm point light (both on), a blue spot and a
// green point light (off): one light of each kind.
std::array<Light, 4> courseRig();
// `light`, switched off (a student switches it on with its number key).
Light off(Light light);

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
// Lesson 02's spot high over the forest: its cone holds the clearing and its crowns.
Light forestSpot();
// A blue spot over the city (off): lesson 03's third light, a perspective 2D map.
Light citySpot();
// A higher, wider blue spot over the city (off): lesson 07's, whose window depth crowds toward 1.
Light cityHighSpot();

}  // namespace shadowlab

#pragma once
// Lesson 08 exercises: Perspective Shadow Maps (seeds 000 §2-3). Pure functions; GLM column
// vectors; right-handed view space looking down -z; camera clip depth in [-1,1] (OpenGL).
// Grade with: ctest -L ex08
#include <glm/glm.hpp>

namespace shadowlab::ex08 {

// EXERCISE 08.1: the post-projective light position (and its class)
// PSM renders the shadow map in the camera's post-projective space (seeds 000 §2), so the light
// must be moved there first. A light is a homogeneous world point: (position, 1) for a point
// light, (-direction, 0) for a directional light (the point at infinity it comes from).
// Compute h = viewProj * light and return:
//   (h.xyz / h.w, +1)  when h.w > 0: a finite point, the light is in front of the camera plane;
//   (h.xyz / h.w, -1)  when h.w < 0: the light is BEHIND the camera (seeds 000 §3); the point is
//                      still h.xyz / h.w, but rays from it reach the scene through infinity;
//   (normalize(h.xyz), 0) when h.w == 0 (|h.w| <= 1e-9 |h.xyz|): the light stays a direction,
//                      parallel to the near plane.
// Example: a directional light exactly behind the camera lands on the plane z = (f+n)/(f-n),
// just behind the unit cube's far face (seeds 000 §4: "distance Q").
glm::dvec4 postProjectiveLight(const glm::dmat4& viewProj, const glm::dvec4& light);

}  // namespace shadowlab::ex08

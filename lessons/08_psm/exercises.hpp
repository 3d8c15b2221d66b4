#pragma once
// Lesson 08 exercises: Perspective Shadow Maps ([Kozlov2004] §2-3). Pure functions; GLM column
// vectors; right-handed view space looking down -z; camera clip depth in [-1,1] (OpenGL).
// Grade with: make grade LESSON=08  (it builds what changed first)
#include <vector>

#include <glm/glm.hpp>
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex08 {

// EXERCISE 08.1: the post-projective light position (and its class)
// PSM renders the shadow map in the camera's post-projective space ([Kozlov2004] §2), so the light
// must be moved there first. A light is a homogeneous world point: (position, 1) for a point
// light, (-direction, 0) for a directional light (the point at infinity it comes from).
// Compute h = viewProj * light and return:
//   (h.xyz / h.w, +1)  when h.w > 0: a finite point, the light is in front of the camera plane;
//   (h.xyz / h.w, -1)  when h.w < 0: the light is BEHIND the camera ([Kozlov2004] §3); the point is
//                      still h.xyz / h.w, but rays from it reach the scene through infinity;
//   (normalize(h.xyz), 0) when h.w == 0 (|h.w| <= 1e-9 |h.xyz|): the light stays a direction,
//                      parallel to the near plane.
// Example: a directional light exactly behind the camera lands on the plane z = (f+n)/(f-n),
// just behind the unit cube's far face ([Kozlov2004] §4: "distance Q").
glm::dvec4 postProjectiveLight(const glm::dmat4& viewProj, const glm::dvec4& light);

// EXERCISE 08.2: the virtual camera's slide
// With the light behind the camera, casters behind the camera end up beyond the plane at infinity
// after the projection (w < 0), and the original PSM cannot put them in its map. Stamminger and
// Drettakis slide the camera back along its own axis until every potential caster is in front of
// it (the "virtual camera"), which is what wastes resolution and makes quality jump when a caster
// stops mattering (Kozlov et al. §3). Given the camera's view matrix (world -> view, looking down
// -z), its near distance zNear and the corners of the potential casters (world), return how far
// back the camera must slide so that every corner lies at least zNear in front of it:
//   shift = max(0, max over corners of (z_view + zNear)),  z_view = (view * (corner, 1)).z
// (a corner at z_view = -zNear is exactly on the near plane: no slide). The lesson then moves the
// eye back by shift and keeps the far plane as far beyond it: near + shift, far + shift.
double virtualCameraShift(const glm::dmat4& view, double zNear, const std::vector<glm::dvec3>& casterCorners);

}  // namespace shadowlab::ex08

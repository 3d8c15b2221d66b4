#pragma once
// Lesson 04 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=04   (it builds what changed first)
// and see yours live with  lesson_04_shadow_volumes --set impl=student
// (silhouettes, the projection, the stencil operations and the z-fail choice then come from YOUR
// functions). Lights are homogeneous: (position, 1) for a point light, (-direction, 0) for the sun.
#include <glm/glm.hpp>

#include "core/mesh.hpp"
#include "algorithms/shadow_volume.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex04 {

// EXERCISE 04.1: silhouette detection from adjacency ([Tarantsev-L12], shadow volumes: "an edge between a
// lit and an unlit face"). The edge (a, b) is shared by the triangle (a, b, c) and its neighbour
// (b, a, d), both counter-clockwise. A triangle faces the light when the light is on the front
// side of its plane: with n = (p1 - p0) x (p2 - p0), dot(n, light.xyz - p0 * light.w) > 0 (exactly
// 0, edge-on, is NOT facing). Return true when exactly one of the two faces the light.
bool isSilhouette(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                  const glm::vec4& light);

// EXERCISE 04.2: the infinite projection matrix ([Everitt2002]): glm::perspective's
// matrix with the far plane at infinity, so the volume's points at infinity (w = 0) are not clipped:
//   [ f/aspect 0  0          0              ]
//   [ 0        f  0          0              ]     f = 1 / tan(fovY / 2)
//   [ 0        0  epsilon-1  nearZ (epsilon-2) ]
//   [ 0        0  -1         0              ]
// Rows as written; GLM stores columns: m[column][row].
glm::mat4 infinitePerspective(float fovY, float aspect, float nearZ, float epsilon);

// EXERCISE 04.3: the stencil operations (what glStencilOpSeparate gets for front and back faces).
// z-pass (the lecture's): where the depth test PASSES, front faces +1 and back faces -1.
// z-fail (Carmack's reverse): where the depth test FAILS, back faces +1 and front faces -1.
// Everything else Keep; counts wrap (IncrWrap / DecrWrap) so the order of faces does not matter.
volume::StencilOps stencilOps(bool zFail);

// EXERCISE 04.4: the near-plane test that picks z-fail. z-pass miscounts a pixel whose eye ray
// starts inside a volume: that happens only when the caster's volume reaches the near rectangle,
// i.e. when the caster meets the convex hull of the near rectangle and the light (a pyramid with the
// light at its apex; for the sun, a prism running from the rectangle toward the light). Return false
// only when the box is wholly outside one of that hull's five planes (the near plane itself and the
// four through each rectangle edge and the light); true otherwise. If the light lies in the near
// plane, return true.
bool volumeMayReachNearPlane(const Aabb& bounds, const volume::NearRect& near, const glm::vec4& light);

}  // namespace shadowlab::ex04

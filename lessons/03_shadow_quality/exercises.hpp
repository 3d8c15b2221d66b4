#pragma once
// Lesson 03 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=03   (it builds what changed first)
// and see yours live with  lesson_03_shadow_quality --set impl=student
// (your caster-culling test and your orthographic fit then drive the sun's shadow pass).
#include <span>

#include <glm/glm.hpp>

#include "algorithms/shadow_math.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex03 {

// EXERCISE 03.1: slope-scaled bias. A receiver tilted by theta from the light direction changes
// depth by tan(theta) per unit across a texel, so the bias must grow with it:
//   bias = min(constant + slope * tan(theta), maxBias),   cosTheta = N.L
// tan(theta) = sqrt(1 - cos^2) / cos. When cosTheta <= 0 (facing away or grazing) return maxBias.
float slopeScaledBias(float constant, float slope, float cosTheta, float maxBias);

// EXERCISE 03.2: the weights of hardware 2x2 PCF (GL_LINEAR on a comparison sampler). texel is
// the lookup position in continuous texel coordinates (uv * size; texel i's centre is i + 0.5).
// With t = texel - 0.5, x0 = floor(t.x), y0 = floor(t.y), f = t - floor(t), return the weights of
// the texels (x0, y0), (x0+1, y0), (x0, y0+1), (x0+1, y0+1): the bilinear weights
//   (1-fx)(1-fy), fx(1-fy), (1-fx)fy, fx fy.
glm::vec4 bilinearPcfWeights(const glm::vec2& texel);

// EXERCISE 03.3: which cube-map face a lookup vector selects, in GL's order 0 +X, 1 -X, 2 +Y,
// 3 -Y, 4 +Z, 5 -Z: the axis of the largest |component|, its sign picking + or -. Ties go to x
// before y before z. Return -1 for the zero vector.
int cubeFace(const glm::vec3& direction);

// EXERCISE 03.4: caster culling. The view needs shadows inside `view` (a convex volume with
// inward planes dot(n, p) + w >= 0). A caster box can shade something there only if the box,
// swept along lightDirection (the direction light travels) to infinity, reaches the volume.
// Return false when some plane separates them: the box is entirely outside it (even its corner
// farthest along n has dot(n, p) + w < 0) AND the sweep does not move toward the inside
// (dot(n, lightDirection) <= 0). Otherwise return true (keep the caster: culling must never drop
// a shadow).
bool casterMayShadow(const Aabb& caster, const shadow::ConvexVolume& view, const glm::vec3& lightDirection);

// EXERCISE 03.5: the orthographic fit of a directional light (without snapping). Build the light
// view with shadow::lightViewAlong(vec3(0), lightDirection). In that space (the light looks down
// -z) take the bounds of the receivers: x and y give the projection's left/right/bottom/top; the
// receivers' smallest z is the far side. Casters only extend the NEAR side: the largest z of any
// caster box corner (toward the light). Use glm::ortho(l, r, b, t, -zmax, -zmin) (a small margin in
// depth is fine), and set texelWorld = max(r - l, t - b) / mapSize. Fill view, projection,
// lightMin, lightMax and texelWorld of the result.
shadow::OrthoFit fitOrthographic(const glm::vec3& lightDirection, std::span<const glm::vec3> receivers,
                                 std::span<const Aabb> casters, int mapSize, bool snap);

}  // namespace shadowlab::ex03

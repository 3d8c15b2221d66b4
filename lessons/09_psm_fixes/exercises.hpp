#pragma once
// Lesson 09 exercises: the paper's fixes to PSM ([Kozlov2004] §3-5). Pure functions; GLM column
// vectors; right-handed view spaces looking down -z; clip depth in [-1,1] (OpenGL).
// Post-projective light encoding as in exercise 08.1: (p, +1) finite in front, (p, -1) finite
// behind the camera, (D, 0) a direction (light at infinity toward +D, rays travel along -D).
// Grade with: make grade LESSON=09  (it builds what changed first)
#include <vector>

#include <glm/glm.hpp>
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex09 {

// EXERCISE 09.1: the inverse projection matrix
// For a light behind the camera, [Kozlov2004] §3 gives the light camera a NEGATIVE near distance and
// a positive far one, Zn = -a, Zf = +a, so Q = Zf / (Zf - Zn) = 1/2 and the stored depth is
//   Z_psm = Q (1 - Zn / Z) = 1/2 (1 + a / Z)          (Direct3D, depth in [0,1]),
// Z the distance along the light camera's axis. In OpenGL conventions (view looks down -z, so
// Z = -z_view; depth in [-1,1]) that is depth = 2 Z_psm - 1 = a / Z: clip w = Z and clip z = a.
// x and y project like an ordinary symmetric perspective with vertical field of view fovY and
// the given aspect (width / height). Return that 4x4 matrix. Warning: the matrix printed in the
// paper has two entries swapped; trust the formula (see docs/psm_conventions.md).
glm::dmat4 inverseProjection(double fovY, double aspect, double a);

// EXERCISE 09.2: the smallest enclosing cone
// [Kozlov2004] §4.1 aims the light camera along the axis of the narrowest cone from the light that
// holds every receiver key point. Given the directions from the light to the points (any
// length, all inside an open hemisphere), return (axis.xyz, halfAngle): a unit axis and the
// least half-angle in radians such that every direction makes an angle <= halfAngle with it.
// Hint: normalise the directions; the cone's circle on the unit sphere is where the sphere meets
// the smallest ball holding the normalised points (Welzl / [Gaertner1999], linear expected time),
// so the axis is that ball's centre, normalised. Return dvec4(0) for an empty input.
glm::dvec4 smallestEnclosingCone(const std::vector<glm::dvec3>& directions);

// EXERCISE 09.3: the visible-face test of the unit cube
// [Kozlov2004] §4.2 renders depth onto the faces of the post-projective cube [-1,1]^3 that the light
// does NOT see. Faces: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; face f has outward normal n_f and lies
// in the plane dot(n_f, x) = 1. Return true when the light sees the face's outer side or sees it
// exactly edge-on (no ray from the light leaves the cube through such a face):
//   finite light (w = +1 or -1) at p:  dot(n_f, p) >= 1;
//   direction light (w = 0) toward D:  dot(n_f, D) >= 0 (the reference allows -1e-9 for rounding).
// (So a point light inside the cube sees no face and uses all 6; outside, 3 to 5 are used.)
bool cubeFaceVisible(int face, const glm::dvec4& postLight);

// EXERCISE 09.4: the texel-size bias
// [Kozlov2004] §5 biases in WORLD space: P_biased = P + L (a + b L_texel), L the unit direction from
// the light to P, L_texel the world size of a shadow-map texel at P. Measure it as the paper says:
// map P by M = worldToClip, move it by one texel in x AND y keeping its depth (in clip space:
// x += (2 / mapSize) w, y += (2 / mapSize) w, since NDC spans 2 units over mapSize texels), map it
// back by M^-1 (divide by w) and take the distance to P (a length, not squared). Return P_biased.
glm::dvec3 texelSizeBias(const glm::dmat4& worldToClip, const glm::dvec3& p, const glm::dvec3& dirFromLight, double a,
                         double b, double mapSize);

// EXERCISE 09.5: LiSPSM's optimal n
// Light Space Perspective Shadow Maps ([Wimmer2004]), lesson 09's third
// technique, warp with a perspective whose centre sits n in front of the view body's near side.
// n -> infinity is the uniform map, n = z0 the strongest (PSM-like) warp; the n that makes the
// aliasing at the near and the far end equal is
//   n_opt = (z0 + sqrt(z0 z1)) / sin(gamma)
// with [z0, z1] the body's depth range along the view direction and gamma the angle between the
// view direction and the light's. Return n_opt; return +infinity when sin(gamma) is 0 (light
// along the view: no warp helps, LiSPSM falls back to the uniform map). z0 > 0 and z1 > z0.
double lispsmOptimalN(double z0, double z1, double gamma);

}  // namespace shadowlab::ex09

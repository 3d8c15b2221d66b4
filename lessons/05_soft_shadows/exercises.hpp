#pragma once
// Lesson 05 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=05   (it builds what changed first)
// and see yours live with  lesson_05_soft_shadows --set impl=student
// (your half-width draws the predicted penumbra edges, your A_frac and its linear approximation
// the plot).
#include <glm/glm.hpp>

#include "algorithms/moment_maps.hpp"
#include "algorithms/soft_shadows.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex05 {

// EXERCISE 05.1: the penumbra half-width of a spherical light (the lecture, after Rogers). A light
// of radius R at distance D from a caster point; the penumbra's centre line lies d further along
// the ray; the receiver's normal makes n.L with the direction to the light. By similar triangles
//   r (n.L) / d = R / D,   so   r = d / (n.L) * R / D.
// The inputs are valid: d >= 0, nDotL > 0, R >= 0, D > 0.
float penumbraHalfWidth(float d, float nDotL, float R, float D);

// EXERCISE 05.2: the visible fraction of the sphere, seen partly from -R to a, t = a / R:
//   A_frac(t) = 1/2 + (1/pi) [ t sqrt(1 - t^2) + asin(t) ]
// and its linear approximation (1 + t) / 2. Clamp t to [-1, 1] first (beyond: all or nothing).
float visibleFraction(float t);
float visibleFractionLinear(float t);

// EXERCISE 05.3: the PCSS filter radius in the shadow map's uv ([Fernando2005]). The blocker search
// found the mean blocker depth zBlocker; the receiver is at zReceiver (both distances along the
// light's axis). The penumbra estimate is w = (zReceiver - zBlocker) / zBlocker * R (the light's
// radius), a width at the receiver; one uv unit there is 2 zReceiver tanHalfFov of world, so the
// radius is w / (2 zReceiver tanHalfFov). Return 0 when zBlocker >= zReceiver (the "blocker" is
// behind the receiver); the other inputs are valid: zBlocker > 0, zReceiver > 0, tanHalfFov > 0.
float pcssFilterRadiusUv(float R, float zReceiver, float zBlocker, float tanHalfFov);

// EXERCISE 05.4: Poisson tap rotation. Each pixel turns the whole tap pattern by its own angle, so
// the pattern's structure becomes noise instead of bands: rotate `tap` by `angle` radians
// counter-clockwise, (x cos a - y sin a, x sin a + y cos a).
glm::vec2 rotateTap(const glm::vec2& tap, float angle);

// EXERCISE 05.5: the light mesh's lookup: the visibility at p averaged from the 8 grid nodes around
// it with trilinear weights. g = (p - grid.origin) / grid.step in node units, clamped to
// [0, nodes - 1]; the cell's first node i0 = min(floor(g), nodes - 2); f = g - i0; node i0 + o
// (o in {0,1}^3) weighs prod over axes of (o ? f : 1 - f). Values: grid.visibility[grid.index(n)].
float lightMeshVisibility(const soft::LightGrid& grid, const glm::vec3& p);

// EXERCISE 05.7: moment shadow maps' Hamburger bound ([Peters2015], 4MSM). A texel of the map holds
// `moments` = (b1, b2, b3, b4), the kernel's mean of (z, z^2, z^3, z^4) over the depths z the light
// sees there. Return the LIT share at the receiver's depth t, in [0, 1]:
//  0. Pull the moments toward 0.5 against rounding: b = (1 - alpha) moments + alpha (0.5, 0.5, 0.5, 0.5).
//  1. Solve B c = (1, t, t^2) for the Hankel matrix B = ((1, b1, b2), (b1, b2, b3), (b2, b3, b4))
//     (it is symmetric positive definite: a 3x3 Cholesky factorisation, or any solver).
//  2. z1 <= z2, the real roots of c0 + c1 z + c2 z^2, and z0 = t are the three depths of the
//     distribution with these moments that puts as much as it can in front of t; delta i weighs
//     w_i = (z_j z_k - b1 (z_j + z_k) + b2) / ((z_i - z_j) (z_i - z_k)), {i, j, k} = {0, 1, 2}.
//  3. The shadow is the weight of the deltas strictly in front of t (z1 and z2 where below t);
//     return 1 - shadow, clamped to [0, 1]. (Three deltas of weights 1/4, 1/2, 1/4 at 0.2, 0.5 and
//     0.8: at t = 0.5 the lit share is 3/4, at t = 0.8 it is 1/4.)
// The inputs are valid: B is positive definite (at least three different depths, or alpha > 0).
double msmLitShare(const glm::dvec4& moments, double t, double alpha);

}  // namespace shadowlab::ex05

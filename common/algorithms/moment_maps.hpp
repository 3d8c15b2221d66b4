#pragma once
// Filterable shadow maps' maths (lesson 05, GL-free; shaders/05_soft_shadows/shadow_filterable.frag
// and depth_moments.frag do the same per texel and per pixel). A map texel stores moments of the
// depth t in [0, 1] of what the light sees; the blur averages them over the kernel, so a texel then
// holds the moments of a DISTRIBUTION of depths, and the lookup bounds the share of it behind the
// receiver's depth:
//   VSM   (t, t^2), Chebyshev's one-sided bound        (Donnelly and Lauritzen, I3D 2006)
//   EVSM  the same of exp(c+ t') and -exp(-c- t'), t' = 2t - 1 (2 or 4 components): the warp makes
//         a far occluder's bound much tighter       (Lauritzen and McCool, GI 2008)
//   MSM   (t, t^2, t^3, t^4) and the Hamburger 4MSM bound: the smallest lit share any distribution
//         with these four moments allows, from three Dirac deltas (Peters and Klein, I3D 2015);
//         16-bit storage through their optimised quantisation
// Each returns the LIT share in [0, 1] (1 - the shadow intensity).
#include <glm/glm.hpp>

namespace shadowlab::soft {

// Chebyshev's one-sided bound of P(x >= t) for a distribution with mean `m1` and raw second moment
// `m2`: 1 for t <= m1, else var / (var + (t - m1)^2) with var = max(m2 - m1^2, minVariance).
double chebyshevUpperBound(double m1, double m2, double t, double minVariance);

// The light-bleeding reduction: the lit share's lowest `amount` (in [0, 1)) cut away and the rest
// stretched back to [0, 1]: (v - amount) / (1 - amount), clamped.
double reduceBleeding(double litShare, double amount);

// EVSM's warp of t in [0, 1]: (exp(cPos t'), exp(cPos t')^2, -exp(-cNeg t'), exp(-cNeg t')^2) with
// t' = 2 t - 1. Exponents above kEvsmMaxExponent overflow a 32-bit float's square; the callers clamp.
inline constexpr double kEvsmMaxExponent = 42.0;
glm::dvec4 evsmMoments(double t, double cPos, double cNeg);
// The lit share from (blurred) EVSM moments: the smaller of the two Chebyshev bounds (the negative
// one only with `four` components). minVariance is in t's units; it is scaled by each warp's slope.
double evsmLitShare(const glm::dvec4& moments, double t, double cPos, double cNeg, bool four, double minVariance);

// MSM's moments of t: (t, t^2, t^3, t^4); their 16-bit form (Peters and Klein's optimised
// quantisation: a fixed 4x4 matrix and an offset that spread the moments over [0, 1]) and back.
glm::dvec4 msmMoments(double t);
glm::dvec4 msmQuantise(const glm::dvec4& moments);
glm::dvec4 msmDequantise(const glm::dvec4& stored);
// The Hamburger 4MSM lit share of depth t from moments b, moment bias `alpha` (b pulled toward 0.5
// by this share: 3e-5 for the 16-bit form in the paper; less suffices in 32-bit floats).
double msmLitShare(const glm::dvec4& moments, double t, double alpha);

}  // namespace shadowlab::soft

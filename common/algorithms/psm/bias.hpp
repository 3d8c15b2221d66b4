#pragma once
// Fix 4 ([Kozlov2004] §5): depth bias in WORLD space, carried into the shadow map by the matrices.
//   P_biased = P + L (a + b L_texel),  then mapped by M (world -> shadow-map clip)
// L: unit direction from the light to P (world); L_texel: the world size of one shadow-map texel
// at P, measured by moving P's map image by c = one texel (keeping its depth) and mapping back:
//   L_texel = | P - unproject(M P + c w) |   with M^-1 (C - I) M folded into ONE matrix K.
// Differences from the seed text (see docs/psm_conventions.md): our M maps to NDC [-1,1], so one
// texel is c = (2/Sx, 2/Sy, 0) in clip units (the paper's texture space [0,1] has 1/Sx); the paper
// squares the length, we keep it a length so a + b L_texel stays a distance; and the shifted point
// is divided by its w (M is projective), which the paper's one-matrix form leaves out.
#include <limits>

#include <glm/glm.hpp>

namespace shadowlab::psm {

// K = M^-1 (C - I) M, C adding (2/Sx, 2/Sy, 0) * w in clip space: d = K (P, 1) is the homogeneous
// world offset of a one-texel step. Throws std::invalid_argument for a singular/non-finite M or a
// map size below 1.
glm::dmat4 texelOffsetMatrix(const glm::dmat4& worldToClip, const glm::dvec2& mapSize);

// K is rank one: (C - I) M P = (2/Sx, 2/Sy, 0, 0) w_clip(P), so K (P, 1) = u (r . (P, 1)) with
// u = M^-1 (2/Sx, 2/Sy, 0, 0) and r = M's last row. The depth pass's vertex shader uses these two
// vectors (shaders/08_psm/depth_psm.vert): one dot product instead of a matrix, and no product of
// M^-1 and M rounded in float.
struct TexelStep {
  glm::dvec4 u{0.0};  // homogeneous world offset per unit of clip w
  glm::dvec4 r{0.0};  // M's last row: clip w = dot(r, (P, 1))
};
TexelStep texelStepFactors(const glm::dmat4& worldToClip, const glm::dvec2& mapSize);

// |P' - P| with P' = (P + d.xyz) / (1 + d.w), d = K (P, 1): the world size of one texel at P
// (+inf when 1 + d.w <= 0: the step crossed the camera's plane at infinity).
double texelWorldSize(const glm::dmat4& texelOffset, const glm::dvec3& p);

// The paper's cheaper form: |d.xyz|^2 (exact only for affine M, and an area, not a length).
double texelWorldSizePaper(const glm::dmat4& texelOffset, const glm::dvec3& p);

// P + dirFromLight min(a + b texelSize, maxOffset); dirFromLight is normalised here; a, b >= 0.
// maxOffset keeps the world shift bounded where the texel is huge or infinite (the far end of a
// PSM at Zf/Zn = 1e6, where one texel step crosses the plane at infinity).
glm::dvec3 biasedWorldPoint(const glm::dvec3& p, const glm::dvec3& dirFromLight, double a, double b, double texelSize,
                            double maxOffset = std::numeric_limits<double>::infinity());

// The unit direction light travels at p: (p - position) for a point light (w = 1), the light's
// travel direction for a directional light given as (-direction, 0).
glm::dvec3 directionFromLight(const glm::dvec4& homogeneousLight, const glm::dvec3& p);

// The constant bias it replaces: depth += bias in NDC after the divide (z_clip += bias * w).
glm::dmat4 constantDepthBiasMatrix(double bias);

// The world distance along the light ray that a constant NDC depth bias amounts to at p (the
// quantity that varies wildly across a PSM, [Kozlov2004] §5, fig. 19). Infinite where the depth does
// not change along the ray.
double worldShiftOfDepthBias(const glm::dmat4& worldToClip, const glm::dvec3& p, const glm::dvec3& dirFromLight,
                             double bias);

}  // namespace shadowlab::psm

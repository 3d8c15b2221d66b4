#pragma once
// The texel density a light's maps give the receivers, predicted from the plan before anything is
// drawn: the criterion of PSM's fall back to the uniform map (psm_plan.hpp, PsmSwitches::fallback).
// At a key point p the shadow's resolution is the spacing of the light's rays through neighbouring
// texels there: bias.hpp's one-texel step (a texel in x and in y at the same map depth, mapped back
// to the world) with its part along the light removed, since moving along a ray changes nothing the
// map can resolve. The screen's resolution at p is one pixel, whose world size grows with p's view
// depth z. Their ratio spacing / z is the aliasing m at p up to the camera's pixels per radian and
// the receiver's orientation, factors that every map fitted to the same camera and receivers shares:
// comparing two maps' means over the key points compares their mean aliasing
// (Stamminger & Drettakis 2002, §2, dp/ds; Wimmer et al. 2004, §3, who choose n by the same measure).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/conventions.hpp"
#include "core/mesh.hpp"

namespace shadowlab::psm {

// The spacing of the light's rays through one texel step of a side x side map at p (world units;
// +inf where the step crosses the camera's plane at infinity). dirFromLight: where light travels at p.
double rayTexelSpacing(const glm::dmat4& worldToClip, int side, const glm::dvec3& p, const glm::dvec3& dirFromLight);

struct TexelDensity {
  double meanAliasing = 0.0;  // mean of spacing / view depth over the points some map holds
  double maxSpacing = 0.0;    // the coarsest spacing among them (world units)
  int points = 0;             // how many points some map holds
};

// Where the camera's pixels meet the receivers, roughly: for cols x rows rays through the centres of
// a grid over the screen, the middle of the ray's way through the nearest rough receiver volume it
// meets, by that middle (from the eye when the eye is inside it; a ray that meets none adds nothing). The aliasing the
// measurement reports is a mean over pixels, which these points sample evenly; the key points (box corners, most of
// them far) would not. Replaces out's contents.
void screenSamples(const CameraFrustum& camera, std::span<const Aabb> receivers, int cols, int rows,
                   std::vector<glm::dvec3>& out);

// Over world points seen by a camera with this view matrix: each point measured in the first of
// `maps` (world -> clip, side x side texels each) whose clip square holds it in front (w > 0).
// light: (position, 1) or (-direction, 0), as homogeneousLight gives it.
TexelDensity predictTexelDensity(const glm::dmat4& cameraView, std::span<const glm::dvec3> points,
                                 std::span<const glm::dmat4> maps, int side, const glm::dvec4& light);

}  // namespace shadowlab::psm

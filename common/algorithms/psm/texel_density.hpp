#pragma once
// The aliasing a light's maps will give the camera's pixels, predicted from the plan before anything
// is drawn: the criterion of PSM's fall back to the uniform map (psm_plan.hpp, PsmSwitches::fallback),
// and the header's "warp's predicted m". At a point p the shadow's resolution is the spacing of the
// light's rays through neighbouring texels there (bias.hpp's one-texel step, its part along the light
// removed: moving along a ray changes nothing the map can resolve); what the viewer sees of it is
// m, screen pixels per texel on the receiver at p (Stamminger & Drettakis 2002, §2, dp/ds; Wimmer et
// al. 2004, §3, who choose n by the same measure).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/conventions.hpp"
#include "core/mesh.hpp"

namespace shadowlab {
struct Scene;
}

namespace shadowlab::psm {

// The spacing of the light's rays through one texel step of a side x side map at p (world units;
// +inf where the step crosses the camera's plane at infinity). dirFromLight: where light travels at p.
double rayTexelSpacing(const glm::dmat4& worldToClip, int side, const glm::dvec3& p, const glm::dvec3& dirFromLight);

struct TexelDensity {
  double meanAliasing = 0.0;  // the mean aliasing m over the points some map holds (predictAliasing)
  double maxSpacing = 0.0;    // the coarsest spacing among them (world units)
  int points = 0;             // how many points some map holds
};

// ---- The aliasing m a map gives the camera's pixels, as the measurement defines it ---------------
// Ray spacing alone misses what makes a warped map alias on walls: its texels are anisotropic, and
// which of their sides a receiver stretches depends on the receiver's orientation (a wall seen at a
// grazing angle spreads one pixel over many texels in one direction and few in the other). So the
// fall-back compares m itself at points on the receivers' surfaces: a pixel's footprint on the
// surface's plane (the rays through the neighbouring pixels cut with it), mapped into the map's
// texels: J (texels per pixel, 2 x 2) and m = 1 / sigma_min(J), as common/measure computes it
// from the lit pass's screen derivatives.

// Where a camera ray meets a receiver volume: the point on its face and the face's normal.
struct SurfaceSample {
  glm::dvec3 point{0.0}, normal{0.0, 1.0, 0.0};
};

// cols x rows rays through the centres of a grid over the screen, each to where it enters the
// nearest receiver volume (a box's face: a block's wall or roof, a height-map cell's top); from
// inside a volume, where it leaves it, the normal turned toward the eye. A ray that meets none
// adds nothing. Replaces out's contents.
void screenSurfaceSamples(const CameraFrustum& camera, std::span<const Aabb> receivers, int cols, int rows,
                          std::vector<SurfaceSample>& out);

// The same rays to the surfaces the camera really sees: the nearest triangle of an object that
// receives shadows (object boxes first, nearest entry first; a CPU ray cast of 144 rays through
// the course's scenes), its geometric normal turned toward the eye. The rough receiver volumes
// above over-fill a city (a street-level ray enters a volume metres before the wall it sees).
void screenSceneSamples(const CameraFrustum& camera, const Scene& scene, int cols, int rows,
                        std::vector<SurfaceSample>& out);

// m at one sample for a camera whose screen is pixelsHigh pixels high (aspect x that wide) and a
// side x side map (world -> clip): 1 / sigma_min of the 2 x 2 Jacobian from screen pixels to map
// texels on the sample's plane; +inf where the map does not hold the point in front, or the pixel's
// neighbours miss the plane. Capped at `cap` (the measurement caps m at 1024).
double pixelAliasing(const CameraFrustum& camera, int pixelsHigh, const SurfaceSample& s, const glm::dmat4& worldToClip,
                     int side, double cap = 1024.0);

// The mean of m over the samples some map holds (each in the first of `maps` holding it), their
// count, and the coarsest ray spacing among them. light: (position, 1) or (-direction, 0), as
// homogeneousLight gives it.
TexelDensity predictAliasing(const CameraFrustum& camera, int pixelsHigh, std::span<const SurfaceSample> samples,
                             std::span<const glm::dmat4> maps, int side, const glm::dvec4& light);

}  // namespace shadowlab::psm

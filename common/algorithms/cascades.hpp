#pragma once
// Cascaded shadow maps, GL-free (lessons/10_showdown/cascades renders them): the view's depth range
// [near, far] cut by the practical split scheme (cascadeSplits, Zhang et al. 2006), mixing the
// logarithmic split (ideal for perspective aliasing) with the uniform one (lambda = 0):
//   z_i = lambda * zn (zf/zn)^(i/N) + (1 - lambda) * (zn + (zf - zn) i/N),  i = 0..N;
// and for each slice of the view frustum a directional light camera fitted to it as lesson 03 fits
// one to the whole view (fitDirectional: the receivers where the slice meets the scene's bounds, the
// casters that can shade them, texel snapping at the cascade's own texel size).
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/light_cameras.hpp"

namespace shadowlab::shadow {

// N + 1 increasing distances from zn to zf (both exact). Throws std::invalid_argument for
// zn <= 0, zf <= zn, count < 1, lambda outside [0, 1] or non-finite values.
std::vector<double> cascadeSplits(double zNear, double zFar, int count, double lambda);
// The same into a caller's buffer (no allocation once warm).
void cascadeSplits(double zNear, double zFar, int count, double lambda, std::vector<double>& out);

// Which cascade shades a point at view depth `depth` (splits: N + 1 increasing distances), and how
// much of the next one is blended in: within the last `band` fraction of cascade i's depth range the
// weight of cascade i + 1 rises linearly from 0 to 1, so the switch leaves no seam (the last cascade
// has nobody to blend into). cascade = -1 outside [splits.front(), splits.back()]: no map covers it.
// shaders/10_showdown/shadow_cascades.frag mirrors it.
struct CascadeBlend {
  int cascade = -1;
  double nextWeight = 0.0;  // in [0, 1): the weight of cascade + 1
};
CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band);

// Each cascade's side at equal total texels: count maps of side s hold about totalSide^2 texels,
// s = floor(totalSide / sqrt(count)). Throws std::invalid_argument for count < 1 or totalSide < 1.
int cascadeSide(int totalSide, int count);

// The viewer whose frustum the cascades split (its view matrix and perspective).
struct CascadeViewer {
  glm::mat4 view{1.0f};
  float fovY = 0.873f, aspect = 1.0f, nearZ = 0.1f, farZ = 200.0f;
};

// A replacement for cascadeSplits (a student's, lesson 10's exercise 10.1); empty: the reference.
using SplitScheme = std::function<std::vector<double>(double zNear, double zFar, int count, double lambda)>;

struct CascadeOptions {
  int count = 4;              // 1..4 slices
  double lambda = 0.75;       // 0 uniform splits, 1 logarithmic
  double farZ = 0.0;          // > 0: the cascades end there; 0: at the deepest point of the scene in view
  DirectionalFitOptions fit;  // per cascade; fit.mapSize is each cascade's side
  // Each cascade draws only the casters that can meet its own light volume (its orthographic box
  // moved back toward the light over the scene: orthoVolumeToward, culled as a spot's frustum is);
  // off: every cascade draws them all.
  bool cullPerCascade = true;
  SplitScheme splitter;
};

struct CascadeSet {
  std::vector<double> splits;        // count + 1 view depths, splits[0] = near
  std::vector<LightCamera> cameras;  // cascade i covers depths [splits[i], splits[i + 1]]
  // The casters some cascade needs (fit.cullCasters: those that can shade its slice of the view),
  // and how many were left out of every cascade. Each camera's own `casters` and `culled` are
  // its pass's: these, less (cullPerCascade) those that cannot reach its light volume.
  std::vector<char> casters;
  int culled = 0;
  std::string problem;  // the splits were unusable (a student's scheme): no cameras, and why
};

// How deep the cascades reach: the farthest corner of `bounds` in front of the viewer, clamped to
// (nearZ, farZ]; farZ when the whole box is behind the near plane.
double cascadeFar(const CascadeViewer& viewer, const Aabb& bounds);

// The slices and their light cameras for a directional light travelling along `direction`.
// Throws std::invalid_argument for count outside 1..4 and as cascadeSplits / fitDirectional do;
// splits from `splitter` that are not count + 1 increasing finite distances from near to far give
// no cameras and say why in `problem`.
CascadeSet fitCascades(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& viewer,
                       const CascadeOptions& options);

// The cascades over splits already made (count + 1 view depths from zNear to zFar, checked as a
// split scheme's are: `problem` says why not), cascade i fitted to the points `receivers(i, out)`
// gives (left empty: its slice of the view frustum where it meets the scene, as fitCascades fits).
// The sample-distribution cascades (algorithms/sdsm) give the points their depth tiles hold.
using CascadeReceivers = std::function<void(int cascade, std::vector<glm::vec3>& out)>;
CascadeSet fitCascadesOver(std::vector<double> splits, double zNear, double zFar, const glm::vec3& direction,
                           const CasterBoxes& scene, const CascadeViewer& viewer, const CascadeOptions& options,
                           const CascadeReceivers& receivers);

// Warping inside each z-partition (Lloyd et al. 2006, [Lloyd2006]): cascade k's map becomes the
// LiSPSM camera of its own slice of the view frustum (psm::fitLispsm: n_opt from the depths the
// slice's receivers span), fitted to the receiver volumes the slice cuts, so the perspective warp
// spreads each cascade's texels over its depth range as LiSPSM spreads one map's over the whole
// view. Each slice from cascade 1 on starts `band` of the previous cascade's depth range earlier:
// the blend band looks the next cascade up there. A slice that cuts no receiver keeps its
// orthographic camera (warped = false).
struct CascadeWarp {
  glm::dmat4 worldToClip{1.0};  // world -> the cascade map's clip space (OpenGL's depth -1..1)
  bool warped = false;
  double n = 0.0;  // the warp's n (world units); infinite where LiSPSM fell back to its uniform map
};
std::vector<CascadeWarp> warpCascades(const CascadeSet& set, const CascadeViewer& viewer, const glm::vec3& direction,
                                      std::span<const Aabb> receivers, double band);

}  // namespace shadowlab::shadow

#pragma once
// The light camera of Perspective Shadow Maps, built in the camera's post-projective space:
// - the original PSM (Stamminger & Drettakis 2002): a virtual camera slid back until every caster
//   is in front of it, then a light camera that cannot see past infinity (the baseline);
// - fix 1 ([Kozlov2004] §3): the inverse projection Zn = -a, Zf = +a for a light behind the camera;
// - fix 2 ([Kozlov2004] §4.1): the light camera aimed along the smallest cone from the light holding
//   the receivers' key points (vertices of the union of B_i ∩ F), with near/far from them.
// Matrices are dmat4 in the conventions of psm/conventions.hpp; worldToClip is the M of §5.
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"
#include "algorithms/psm/clipping.hpp"
#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/enclosing_cone.hpp"

namespace shadowlab::psm {

enum class LightProjection {
  Perspective,          // light in front: depth grows with distance from the light
  Inverse,              // fix 1: light behind, Zn = -a, Zf = +a, the ray wraps through infinity
  ReversedPerspective,  // original PSM, light behind: only Z >= far is seen, depth falls with Z
  Orthographic          // light parallel to the near plane: a direction in post-projective space
};

struct LightCamera {
  LightProjection kind = LightProjection::Perspective;
  glm::dmat4 view{1.0};             // post-projective -> light view (right-handed, looks down -z)
  glm::dmat4 projection{1.0};       // light view -> light clip, depth range applied
  glm::dmat4 postToClip{1.0};       // projection * view
  glm::dmat4 worldToClip{1.0};      // postToClip * camera viewProj: world point -> shadow-map clip
  glm::dvec3 eye{0.0};              // post-projective light position (Orthographic: behind the points)
  glm::dvec3 axis{0.0, 0.0, -1.0};  // unit viewing direction in post-projective space
  double halfAngle = 0.0;           // of the square frustum's inscribed cone (0 for Orthographic)
  double zNear = 0.0, zFar = 0.0;   // distances along axis (Inverse: -a and +a)
};

// The steps a lesson may replace with a student's version (impl=student); empty: the reference.
struct PsmSteps {
  std::function<Cone(std::span<glm::dvec3>)> cone;  // fix 2: smallestEnclosingCone
  // fix 1: inverseProjection(fovY, aspect, a) in [-1,1] depth (the depth range is applied after)
  std::function<glm::dmat4(double, double, double)> inverseProjection;
  std::function<bool(int, const PostProjectiveLight&)> faceVisible;  // fix 3: cubeFaceVisible
};

// What a light behind the camera gets (after the original PSM's slide, or with fix 1).
enum class BehindProjection { Inverse, Reversed };

struct PsmOptions {
  DepthRange depthRange = DepthRange::MinusOneToOne;
  // Wider cones spread the map too thin ([Kozlov2004] §4: near 180 degrees the quality collapses);
  // past this the fit reports ConeTooWide so the caller switches to cube faces (§4.2).
  double maxHalfAngle = 1.3962634015954636;  // 80 degrees
  // InFront: near = nearFraction * (nearest receiver distance), leaving room for casters between
  // the light and the receivers (render casters with depth clamp to keep the ones beyond it).
  double nearFraction = 0.5;
  // A single map that may not switch to cube faces (the original PSM): a cone wider than
  // maxHalfAngle is narrowed to it instead of failing, and the receivers outside it go unshadowed.
  bool capWideCones = false;
  BehindProjection behind = BehindProjection::Inverse;
  PsmSteps steps;
};

enum class FitStatus { Ok, NoReceivers, ConeTooWide };

struct PsmFit {
  FitStatus status = FitStatus::NoReceivers;
  PostProjectiveLight light;
  Cone cone;           // in post-projective space, apex at the light (invalid for Direction)
  LightCamera camera;  // meaningful when status == Ok
};

// Fix 1's matrix in GL conventions: light view space looks down -z, Z = -z_view is the distance
// along the axis. Clip w = Z; depth/w = a / Z in [-1,1] (Z_psm = (1 + a/Z)/2 in [0,1], [Kozlov2004]
// §3): Z = -a -> near, Z -> +-inf -> middle, Z = +a -> far. x, y as a symmetric perspective with
// vertical field of view fovY. Throws std::invalid_argument for a <= 0, fovY outside (0, pi),
// aspect <= 0 or non-finite values.
glm::dmat4 inverseProjection(double fovY, double aspect, double a, DepthRange range = DepthRange::MinusOneToOne);

// Original PSM with the light behind: Z >= f maps to depth from +1 (Z = f) down to -1 (Z -> inf).
glm::dmat4 reversedProjection(double fovY, double aspect, double f, DepthRange range = DepthRange::MinusOneToOne);

// Fits the light camera to post-projective key points (fix 2 + fix 1, or the original's reversed
// projection with options.behind). `scratch` is reused for the cone's directions. cameraViewProj
// only fills worldToClip.
PsmFit fitLightCamera(const PostProjectiveLight& light, std::span<const glm::dvec3> postPoints,
                      const glm::dmat4& cameraViewProj, const PsmOptions& options, std::vector<glm::dvec3>& scratch);

// Per-frame helper owning its buffers: clip receivers against the frustum, move the key points
// to post-projective space, fit. No allocation once the buffers are warm.
class PsmFitter {
 public:
  const PsmFit& fit(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                    const PsmOptions& options = {});
  std::span<const glm::dvec3> worldKeyPoints() const { return world_; }
  std::span<const glm::dvec3> postKeyPoints() const { return post_; }
  const PsmFit& result() const { return fit_; }

 private:
  std::vector<glm::dvec3> world_, post_, scratch_;
  PsmFit fit_;
};

// ---- Original PSM (baseline) ----------------------------------------------------------------
// How far to slide the camera back along its view axis so every caster corner is in front of the
// camera plane by at least zNear: the virtual camera of Stamminger & Drettakis. 0 when already so.
double virtualCameraShift(const CameraFrustum& camera, std::span<const Aabb> casters);
// The same over caster corners (world): max(0, max (view * corner).z + zNear).
double virtualCameraShift(const glm::dmat4& view, double zNear, std::span<const glm::dvec3> corners);

struct OriginalPsm {
  double shift = 0.0;           // 0 unless the light is behind the real camera
  CameraFrustum virtualCamera;  // eye moved back by shift; near and far moved with it
  PsmFit fit;                   // in the virtual camera's post-projective space
};

// The baseline: receivers are clipped against the REAL frustum, then everything happens in the
// virtual camera's space (Behind -> ReversedPerspective).
OriginalPsm fitOriginalPsm(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                           std::span<const Aabb> casters, const PsmOptions& options,
                           std::vector<glm::dvec3>& worldScratch, std::vector<glm::dvec3>& postScratch,
                           std::vector<glm::dvec3>& dirScratch);

}  // namespace shadowlab::psm

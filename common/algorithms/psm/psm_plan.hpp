#pragma once
// One frame of a Perspective Shadow Map for one light, planned GL-free: in which camera's
// post-projective space the map lives, where the light lands there, which points the light camera
// is fitted to, and the maps to render with their world -> shadow-map clip matrices. The original
// PSM (Stamminger & Drettakis 2002) and each of the four fixes of Kozlov et al. ("Perspective Shadow
// Maps: Care and Feeding", GPU Gems 1 ch. 14) are switches:
//   original            a light behind the camera: the camera slid back until every potential caster
//                       is in front of it (the virtual camera), then a light camera that sees only
//                       past the receivers; the light camera fitted to EVERY object inside the
//                       (virtual) view frustum; one map whatever the cone's width (capped at
//                       singleMapMaxHalfAngle: what falls outside goes unshadowed)
//   fix 1 (§3)          inverseProjection: no slide; the inverse projection orders a light ray
//                       through infinity
//   fix 2 (§4.1)        receiverClipping: fitted to the receivers' rough volumes clipped by the
//                       REAL view frustum only (casters are on the rays to them anyway)
//   fix 3 (§4.2)        faces: the unit cube's faces the light cannot see, one map each (Auto: when
//                       the cone is wider than options.maxHalfAngle or there is none)
//   fix 4 (§5)          the world-space texel-size bias: in the shaders, from mapTexelOffset()
//   fallback            a directional light whose warp would alias more than the uniform map:
//                       the uniform map (texel_density.hpp predicts both from the key points; the
//                       paper's advice where the warp cannot help, and LiSPSM's n -> infinity)
// The total texels are the caller's: a face set splits them (faceMapSize).
#include <array>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/clipping.hpp"
#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/cube_faces.hpp"
#include "algorithms/psm/psm_camera.hpp"
#include "algorithms/psm/texel_density.hpp"
#include "core/mesh.hpp"

namespace shadowlab::psm {

enum class FaceMode { Never, Auto, Always };

struct PsmSwitches {
  bool inverseProjection = true;    // fix 1; false: the original's virtual camera slide
  bool receiverClipping = true;     // fix 2; false: fitted to every object inside the frustum
  FaceMode faces = FaceMode::Auto;  // fix 3
  // The fall back to the uniform map (directional lights): when the warped maps' predicted mean
  // aliasing over the key points exceeds fallbackRatio times the uniform map's at the same texels
  // (mapSide^2, a face set sharing them). Off: the warp whatever it costs (lesson 09 shows why).
  bool uniformFallback = false;
  double fallbackRatio = 1.0;
  int mapSide = 2048;
  int screenHeight = 720;                             // the camera's pixels high (the predicted m is per pixel)
  PsmOptions options;                                 // depth range, the Auto switch's cone limit, near fraction, steps
  double singleMapMaxHalfAngle = 1.5620696805349117;  // 89.5 degrees: the widest single map (faces Never)
  // A light this close to parallel to the near plane (|h.w| <= tolerance |h.xyz|) is taken as a
  // direction: its post-projective point lies over 1,000 cube sizes away. A perspective map from
  // there crams the receivers into the last 1e-3 of its depth, which float cannot resolve at the GL
  // boundary (speckled acne, measured); an orthographic one along the light is linear in depth, and
  // its rays differ from the true ones by at most (cube size)^2 / distance, about 3 texels of a 2048
  // map at the far corners and a tenth of one for casters near their receivers
  // (conventions.hpp keeps 1e-9 for the double-precision maths).
  double directionTolerance = 1e-3;
  // A student's versions (impl=student); empty: the reference.
  std::function<PostProjectiveLight(const glm::dmat4&, const glm::dvec4&)> toPostProjective;  // ex08.1
  std::function<double(const CameraFrustum&, std::span<const Aabb>)> virtualShift;            // ex08.2
};

enum class PlanStatus {
  Ok,
  NothingInView,  // no receiver inside the view frustum: nothing can be shadowed
  NoLightCamera   // a single map was asked for and no cone from the light holds the points
};

struct PsmMap {
  LightCamera camera;  // camera.worldToClip is the matrix the depth pass and the lookup use
  int face = -1;       // the unit cube's face it covers (0 +x ... 5 -z), -1 for the single map
};

struct PsmPlan {
  PlanStatus status = PlanStatus::NothingInView;
  PostProjectiveLight realLight;  // the light after the REAL camera's projection
  PostProjectiveLight light;      // after `camera`'s (the virtual camera when slid)
  CameraFrustum camera;           // whose post-projective space the maps live in
  double shift = 0.0;             // how far the original slid the camera back (0: not slid)
  Cone cone;                      // the single map's cone (invalid for faces or a direction)
  bool faces = false;             // true: one map per hidden face of the unit cube
  unsigned faceMask = 0;          // the hidden faces (faces only)
  std::array<PsmMap, 6> maps{};
  int mapCount = 0;
  int pointsOutside = 0;  // key points outside a capped single map (unshadowed)
  // The key points' depth in `camera`'s post-projective space, z in [-1, 1], and the nearest one's
  // distance from the eye: with a near plane far nearer than the receivers they crowd against
  // z = 1 (the original's weakness: its map spends texels and depth on the empty rest).
  double postZMin = 0.0, postZMax = 0.0, nearestDepth = 0.0;
  // The predicted texel densities (directional lights, the switch on or off): the warp's and the
  // uniform map's; fallback: maps[0] is the uniform map (kind Orthographic, in world space).
  TexelDensity warped, uniform;
  bool fallback = false;
  std::span<const PsmMap> used() const { return {maps.data(), std::size_t(mapCount)}; }
};

// Side of each of `count` square maps that together hold about side * side texels (at least 1).
int faceMapSize(int side, int count);

// K = M^-1 (C - I) M of fix 4 for a map of `size` texels per side (bias.hpp, texelOffsetMatrix).
glm::dmat4 mapTexelOffset(const glm::dmat4& worldToClip, int size);

// Plans the maps of one light for one frame. Owns its buffers: no allocation once warm.
class PsmPlanner {
 public:
  // receivers: the rough receiver volumes (receiverVolumes); objects: every object's box (the
  // original fits to all of them); casters: the potential casters' boxes (for the slide).
  const PsmPlan& plan(const CameraFrustum& camera, const glm::dvec4& light, std::span<const Aabb> receivers,
                      std::span<const Aabb> objects, std::span<const Aabb> casters, const PsmSwitches& switches);
  // The surfaces the camera sees (screenSceneSamples), for the fall-back's prediction from the next
  // plan() on; none: the prediction samples the receiver volumes (screenSurfaceSamples).
  void setSeen(std::span<const SurfaceSample> seen) { seen_.assign(seen.begin(), seen.end()); }
  const PsmPlan& result() const { return plan_; }
  std::span<const glm::dvec3> worldKeyPoints() const { return world_; }  // what the light camera is fitted to
  std::span<const glm::dvec3> postKeyPoints() const { return post_; }    // the same in plan().camera's space

 private:
  void fitSingle(const PsmSwitches& s);
  void fitFaces(const PsmSwitches& s);
  void chooseFallback(const PsmSwitches& s, const CameraFrustum& camera, const glm::dvec4& light,
                      std::span<const Aabb> receivers);
  std::vector<glm::dvec3> world_, post_, scratch_;
  std::vector<SurfaceSample> samples_, seen_;
  PsmPlan plan_;
};

}  // namespace shadowlab::psm

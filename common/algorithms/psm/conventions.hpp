#pragma once
// Conventions shared by every function in common/algorithms/psm (see docs/psm_conventions.md):
// - Right-handed world and view space; a camera looks down its view-space -z. GLM column vectors:
//   a point p is transformed as M * vec4(p, 1), matrices compose right to left.
// - Camera clip space is OpenGL's: after the divide, the view frustum is the cube [-1,1]^3
//   ("the unit cube" of [Kozlov2004] §3-4: side 2, centre 0). Post-projective space is that
//   divided space. Shadow-map depth is produced in [-1,1] by default; DepthRange::ZeroToOne
//   remaps it for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) (GL 4.5 / ARB_clip_control),
//   with [-1,1] as the fallback where clip control is missing.
// - A light is a homogeneous world point: (position, 1) for a point light, (-direction, 0) for a
//   directional light (the point at infinity the light comes FROM; `direction` is where it travels).
//   After the camera's P*V the light is h = P*V*light. h.w > 0: a finite point in front of the
//   camera plane (InFront); h.w < 0: the light is behind the camera plane and the order of points
//   along its rays passes through infinity (Behind, [Kozlov2004] §3); h.w == 0 (within a relative
//   tolerance): the light stays a direction in post-projective space, parallel to the near plane.
// - Everything is double precision: Zf/Zn up to 1e6 puts a directional light 2e-6 behind the
//   cube's far face, which float cannot resolve. Convert with glm::mat4(m) only at the GL boundary.
#include <glm/glm.hpp>

#include "core/light.hpp"

namespace shadowlab::psm {

// Depth range of the shadow-map clip space a light camera writes.
enum class DepthRange { MinusOneToOne, ZeroToOne };

// Maps NDC depth [-1,1] onto the chosen range (identity for MinusOneToOne). Pre-multiply it.
glm::dmat4 depthRangeRemap(DepthRange range);

// The [lo, hi] depth interval of a range, for checks.
double depthRangeLow(DepthRange range);
inline double depthRangeHigh(DepthRange) { return 1.0; }

enum class PostLightKind { InFront, Behind, Direction };

struct PostProjectiveLight {
  PostLightKind kind = PostLightKind::InFront;
  glm::dvec4 homogeneous{0.0};  // P*V*light, undivided
  glm::dvec3 position{0.0};     // h.xyz / h.w (InFront, Behind); unused for Direction
  glm::dvec3 direction{0.0};    // unit; Direction: the light sits at infinity toward +direction
                                // and its rays travel along -direction. Finite: unit (position - 0)
};

// |h.w| <= kDirectionTolerance * |h.xyz| counts as a direction: beyond ~1e9 cube sizes a point
// light is parallel to double precision, and a finite position there would cost digits.
inline constexpr double kDirectionTolerance = 1e-9;

// (position, 1) or (-direction, 0); throws std::invalid_argument on NaN or a zero direction.
glm::dvec4 homogeneousLight(const Light& light);

// Classifies h = viewProj * light. Throws std::invalid_argument when the light or the matrix is
// not finite, or the light is the zero vector.
PostProjectiveLight toPostProjective(const glm::dmat4& viewProj, const glm::dvec4& light,
                                     double directionTolerance = kDirectionTolerance);

// A camera as the PSM code needs it. Built by makeCamera, which validates its inputs.
struct CameraFrustum {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dmat4 viewProj{1.0};
  glm::dmat4 invViewProj{1.0};
  double fovY = 0.0, aspect = 1.0, zNear = 0.0, zFar = 0.0;
};

// OpenGL perspective (depth [-1,1]) in double. Throws std::invalid_argument naming the value for
// fovY outside (0, pi), aspect <= 0, zNear <= 0, zFar <= zNear, or anything non-finite.
glm::dmat4 perspectiveGL(double fovY, double aspect, double zNear, double zFar);
CameraFrustum makeCamera(const glm::dmat4& view, double fovY, double aspect, double zNear, double zFar);

// Right-handed look-at in double looking from eye along `forward` (any length), with an up
// vector chosen away from `forward` when none is given.
glm::dmat4 lookAlong(const glm::dvec3& eye, const glm::dvec3& forward);

// An arbitrary unit vector perpendicular to v (v need not be unit; must be non-zero).
glm::dvec3 anyPerpendicular(const glm::dvec3& v);

bool isFinite(const glm::dmat4& m);
bool isFinite(const glm::dvec3& v);
bool isFinite(const glm::dvec4& v);
// Throws std::invalid_argument("<what> is not finite") if any entry is NaN or infinite.
void requireFinite(const glm::dmat4& m, const char* what);
void requireFinite(const glm::dvec3& v, const char* what);

}  // namespace shadowlab::psm

#pragma once
// Fix 3 ([Kozlov2004] §4.2): depth maps on the faces of the post-projective unit cube that the light
// does NOT see, one off-centre projection per face from the light's post-projective position
// ("a cube map with a shifted centre": lookup vector = point - light position). 3 to 5 faces for
// a light outside the cube, all 6 for a point light inside it.
// Faces: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z (far), 5 -z (near); the cube is [-1,1]^3.
// The faces are separate 2D maps (the paper allows either): a hardware cube texture picks its face
// by the lookup vector's major axis, which matches the unit cube's faces only for a light at the
// cube's centre, so cubeFaceOf (the face the ray from the light leaves the cube through) decides.
#include <array>
#include <span>

#include <glm/glm.hpp>

#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/psm_camera.hpp"

namespace shadowlab::psm {

glm::dvec3 cubeFaceNormal(int face);  // outward; throws std::invalid_argument outside 0..5

// True when the light sees the face's outer side: dot(n, L') > 1 for a finite light (in front or
// behind alike: the projection is geometric), dot(n, D) > 0 for a direction. A face seen edge-on
// counts as visible: no ray from the light leaves the cube through it.
bool cubeFaceVisible(int face, const PostProjectiveLight& light);
unsigned hiddenFaceMask(const PostProjectiveLight& light);  // bit f set: face f carries a map
// The same with a replaceable visibility test (a student's, impl=student); empty: cubeFaceVisible.
unsigned hiddenFaceMask(const PostProjectiveLight& light, const PsmSteps& steps);
int hiddenFaceCount(const PostProjectiveLight& light);

// The hidden face through which the ray from the light through `point` leaves the cube (for a
// direction: the ray through the point travelling along -direction); -1 if the point is the light.
int cubeFaceOf(const glm::dvec3& point, const PostProjectiveLight& light);
// The same among the faces of `hiddenMask` (as hiddenFaceMask gives it).
int cubeFaceOf(const glm::dvec3& point, const PostProjectiveLight& light, unsigned hiddenMask);

// [Kozlov2004] §4.2: lookup vector = point - light position; a Direction light gives -direction.
glm::dvec3 cubeLookupVector(const glm::dvec3& point, const PostProjectiveLight& light);

struct CubeFaceCamera {
  bool used = false;   // hidden face with a map
  LightCamera camera;  // Orthographic faces keep view = identity and the whole map in projection
};

struct CubeFaceSet {
  PostProjectiveLight light;
  unsigned hiddenMask = 0;
  std::array<CubeFaceCamera, 6> faces{};
};

// One camera per hidden face (options.steps.faceVisible decides which are hidden). The far plane is the face itself;
// the near plane (InFront) is nearFraction of the closest distance of the cube region the face serves, or of the
// closest receiver when the light is inside the cube; Behind uses fix 1's inverse projection with a = that closest
// distance. postReceivers may be empty.
CubeFaceSet cubeFaceCameras(const PostProjectiveLight& light, const glm::dmat4& cameraViewProj,
                            std::span<const glm::dvec3> postReceivers, const PsmOptions& options = {});

// The closest distance along the face's normal from the light to the part of the cube whose rays
// leave through that face (0 when the light is inside the cube). Exposed for tests and lessons.
double cubeFaceRegionMinDistance(const glm::dvec3& lightPosition, int face);

}  // namespace shadowlab::psm

#pragma once
// The light cameras of the uniform shadow-map technique (lesson 03), GL-free: for each kind of
// light, the camera its map is rendered from and the casters that camera must draw.
//   directional  an orthographic frustum fitted to the receivers the view needs (or the whole
//                scene), casters culled against the light volume swept from the view frustum
//   spot         a perspective frustum around the cone, casters culled against it
//   point        six 90-degree faces (a cube map), casters culled per face, faces whose frustum
//                misses the view frustum skipped
// The GL half (lessons/03_shadow_quality/uniform_maps) renders what these say; the tests check them here.
#include <array>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/shadow_math.hpp"
#include "core/light.hpp"
#include "core/mesh.hpp"

namespace shadowlab::shadow {

// One light camera: what it sees and which casters it draws.
struct LightCamera {
  glm::mat4 view{1.0f}, projection{1.0f};
  std::vector<char> casters;  // per scene object: 1 when drawn into this camera's map
  int culled = 0;             // shadow casters left out
  float texelWorld = 0.0f;    // directional: the world size of one texel across the map
  bool skipped = false;       // cube face: its frustum misses the view, so it is not rendered
  glm::mat4 viewProj() const { return projection * view; }
};

// The scene as the culling tests see it: every object's world box, which objects cast shadows,
// and the bounds of everything.
struct CasterBoxes {
  std::span<const Aabb> boxes;
  std::span<const char> casts;  // same length as boxes
  Aabb bounds;
};

// Replaceable steps, so a lesson can run a student's version (impl=student); empty: the reference.
using CasterTest = std::function<bool(const Aabb&, const ConvexVolume&, const glm::vec3&)>;
using OrthoFitter =
    std::function<OrthoFit(const glm::vec3&, std::span<const glm::vec3>, std::span<const Aabb>, int, bool)>;

struct DirectionalFitOptions {
  bool fitToView = true;    // receivers: the scene bounds inside the view frustum; false: the whole scene
  bool snap = true;         // texel snapping (only when fitted to the view: a scene fit never moves)
  bool cullCasters = true;  // leave out casters that cannot shade anything in view
  int mapSize = 2048;
  CasterTest casterTest;  // default casterMayShadow
  OrthoFitter fitter;     // default fitOrthographic
  TexelSnapper snapper;   // default snapToTexels (with the default fitter)
};

// Caster culling against a light volume (a spot's frustum, a cube face's, a cascade's box): scene
// object i is kept in camera.casters when it casts, `among` keeps it (empty: every caster) and
// (with `cull`) its box can meet the volume; camera.culled counts the casters left out.
void cullAgainst(LightCamera& camera, const CasterBoxes& scene, const ConvexVolume& lightVolume, bool cull,
                 std::span<const char> among = {});
// An orthographic light camera's box with its near side moved back toward the light to hold all of
// `bounds`: what its map can receive a caster's depth from when the depth pass clamps depth
// instead of clipping at the near plane (GL_DEPTH_CLAMP: a caster nearer than it still writes).
ConvexVolume orthoVolumeToward(const LightCamera& ortho, const Aabb& bounds);

// A directional light travelling along `direction`. `view`: the viewer's frustum (never a debug
// camera's). Throws std::invalid_argument as fitOrthographic does.
LightCamera fitDirectional(const glm::vec3& direction, const CasterBoxes& scene, const ConvexVolume& view,
                           const DirectionalFitOptions& options);
// The same with the receivers given: the points the map must cover (a sample distribution's tight
// bounds, lessons/10_showdown/sdsm); casters still culled against `view`. Empty receivers: as
// fitDirectional.
LightCamera fitDirectionalTo(const glm::vec3& direction, const CasterBoxes& scene, const ConvexVolume& view,
                             std::span<const glm::vec3> receivers, const DirectionalFitOptions& options);

// The spot's frustum: a square perspective whose field of view holds the cone,
// min(2 * spotOuter + 0.05, 3) radians, from nearZ to max(farZ, nearZ + 0.1).
float spotFieldOfView(const Light& spot);
LightCamera spotCamera(const Light& spot, float nearZ, float farZ, const CasterBoxes& scene, bool cullCasters);

// A 2D map's light camera with what its lookup needs: a directional light's fitted orthographic
// camera (fitDirectional with `directional`) or a spot's perspective frustum (spotCamera from
// spotNear to spotFar, casters culled when directional.cullCasters), the texture matrix (world ->
// [0,1]^3; a spot's takes its view-projection whole, as lesson 02 builds it) and the texel size
// (orthographic: the world size of one texel; perspective: 2 tan(fov / 2) / size, a texel's width at
// unit distance). Shared by every 2D-map technique (uniform maps, hybrid maps). Throws
// std::invalid_argument for a point light (it needs a cube) and as fitDirectional does.
struct Map2DCamera {
  LightCamera camera;
  glm::mat4 textureMatrix{1.0f};
  float texel = 0.0f;
  bool perspective = false;
};
Map2DCamera fitMap2D(const Light& light, const CasterBoxes& scene, const ConvexVolume& view,
                     const DirectionalFitOptions& directional, float spotNear, float spotFar);

// The point light's six faces in GL's cube order (+X, -X, +Y, -Y, +Z, -Z), each a 90-degree
// perspective from nearZ to max(farZ, nearZ + 0.1), so that the map is what samplerCube reads.
std::array<LightCamera, 6> cubeCameras(const glm::vec3& position, float nearZ, float farZ, const CasterBoxes& scene,
                                       const ConvexVolume& view, bool cullCasters, bool skipFaces);

}  // namespace shadowlab::shadow

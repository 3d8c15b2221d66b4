#pragma once
// Stencil shadow volumes as GL-free maths (lesson 04; [Tarantsev-L12], shadow volumes; Everitt and
// Kilgard, "Practical and Robust Stenciled Shadow Volumes", 2002):
//   - the edge adjacency of a mesh, built once, with a closedness report (volumes need closed
//     meshes: an open edge leaves a hole in the volume and the stencil count goes wrong),
//   - the silhouette toward a light (an edge between a face toward the light and one away),
//   - the volume itself: quads from the silhouette out to infinity (w = 0) and the two caps,
//   - the infinite far-plane projection that keeps those points at infinity unclipped,
//   - the near-plane test that says when z-pass can fail and z-fail is needed,
//   - the stencil operations of z-pass and z-fail, and the scissor rectangle of a light's reach.
// Lights are homogeneous: (position, 1) for point and spot lights, (-direction, 0) for a
// directional one (the direction TOWARD the light at infinity).
#include <cstdint>
#include <string>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/light.hpp"
#include "core/mesh.hpp"
#include "core/scene.hpp"

namespace shadowlab::volume {

// ---- Edge adjacency ------------------------------------------------------------------------------
// One undirected edge of the welded mesh. `a -> b` is the direction face0 walks it (counter-clockwise
// order); face1 walks b -> a. face1 = -1 on a boundary (open) edge.
struct Edge {
  std::uint32_t a = 0, b = 0;
  std::int32_t face0 = -1, face1 = -1;
};

struct EdgeAdjacency {
  std::vector<glm::vec3> positions;      // welded: positions closer than the weld tolerance are one
  std::vector<std::uint32_t> triangles;  // 3 welded indices per face (faces collapsed by welding dropped)
  std::vector<glm::vec4> planes;         // per face: (unit normal, -normal . corner), positive side = front
  std::vector<Edge> edges;
  // GL_TRIANGLES_ADJACENCY order, 6 per face: v0, opposite(v0 v1), v1, opposite(v1 v2), v2, opposite(v2 v0).
  // A boundary edge gets the face's own third vertex: the "neighbour" (b, a, c) then faces the
  // other way, so a boundary edge always counts as a silhouette edge of a face toward the light.
  std::vector<std::uint32_t> adjacencyIndices;
  std::size_t boundaryEdges = 0;      // used by one face: the mesh has a hole
  std::size_t nonManifoldEdges = 0;   // used by three or more faces (paired as far as possible)
  std::size_t inconsistentEdges = 0;  // two faces walking the edge the same way (flipped winding)
  bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && inconsistentEdges == 0; }
  std::size_t faceCount() const { return triangles.size() / 3; }
  // "closed" or e.g. "open: 4 boundary edges, 1 flipped" for the UI.
  std::string report() const;
};

// Throws std::invalid_argument on an index past the positions (naming it).
EdgeAdjacency buildAdjacency(const Mesh& mesh, float weldEpsilon = 1e-5f);

// ---- Lights and silhouettes ----------------------------------------------------------------------
// (position, 1) or (-direction, 0), see the top of the file.
glm::vec4 homogeneousLight(const Light& light);
// The face's plane evaluated at the light: > 0 when the face is turned toward it.
inline bool facesLight(const glm::vec4& plane, const glm::vec4& light) { return glm::dot(plane, light) > 0.0f; }

// A silhouette edge, oriented as the face TOWARD the light walks it.
struct SilhouetteEdge {
  std::uint32_t a = 0, b = 0;
};
// A silhouette test on an edge (a, b) between the faces (a, b, c) and (b, a, d): isSilhouette
// below, or a student's version of it (lesson 04, exercise 04.1).
using SilhouetteTest = bool (*)(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                                const glm::vec4& light);
// Edges between a face toward the light and a face away from it, plus the boundary edges of faces
// toward the light (what an open mesh's volume needs under z-pass). `light` in the mesh's space.
// With `test`, paired edges are judged by it instead of the faces' planes.
// `twoSided` (open meshes): an open surface shows the light its back wherever a face is turned
// away, so those faces cast too, as if flipped: a second volume over the faces away from the
// light, whose edges are the same silhouette edges again (flipped faces walk them the same way)
// and the faces' boundary edges reversed. Without it an open chimney's far walls, seen from the
// light through its top, cast nothing (the leak gpu.04_shadow_volumes.model_open_mesh found).
std::vector<SilhouetteEdge> findSilhouette(const EdgeAdjacency& adj, const glm::vec4& light,
                                           SilhouetteTest test = nullptr, bool twoSided = false);
// The same test written on four points, as the exercise asks: edge (a, b) shared by the faces
// (a, b, c) and (b, a, d) is a silhouette when exactly one of them faces the light.
bool isSilhouette(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                  const glm::vec4& light);

// ---- The volume ----------------------------------------------------------------------------------
// Triangles of the volume as vec4: (object-space position, 1) for a point on the mesh, (position, 0)
// for the same point pushed to infinity away from the light (the vertex shader turns it into the
// direction P * L.w - L.xyz, with w = 0). Every triangle's front faces OUT of the volume.
//   sides:      two triangles per silhouette edge (a, b walked by the face toward the light:
//               (b, a, a_inf), (b, a_inf, b_inf))
//   caps:       the faces AWAY from the light, reversed, where they are (near cap), and as they are
//               at infinity (far cap). Caps from the faces away from the light keep a lit surface
//               from coinciding with its own cap. z-pass never needs the caps; z-fail does.
struct VolumeCounts {
  std::size_t silhouetteEdges = 0, sideTriangles = 0, capTriangles = 0;
};
VolumeCounts buildVolume(const EdgeAdjacency& adj, const glm::vec4& light, bool caps, std::vector<glm::vec4>& out,
                         std::vector<SilhouetteEdge>* silhouette = nullptr, SilhouetteTest test = nullptr,
                         bool twoSided = false);

// ---- Projection ------------------------------------------------------------------------------------
// OpenGL perspective (depth in [-1, 1]) with the far plane at infinity: a point at infinity, (x, y,
// z, 0), lands at depth 1 - epsilon/2 instead of being clipped. epsilon > 0 keeps it strictly inside
// the clip volume despite rounding (Everitt and Kilgard: about 2^-22 for a 24-bit depth buffer).
//   [ f/a  0   0        0           ]
//   [ 0    f   0        0           ]     f = 1 / tan(fovY / 2)
//   [ 0    0   eps-1    n (eps-2)   ]
//   [ 0    0   -1       0           ]
inline constexpr float kInfiniteEpsilon = 4.8e-7f;
glm::mat4 infinitePerspective(float fovY, float aspect, float nearZ, float epsilon = kInfiniteEpsilon);
// The same for any finite perspective matrix (glm::perspective form): its near plane kept, its far
// plane moved to infinity. Throws std::invalid_argument for a matrix that is not a perspective one.
glm::mat4 makeFarInfinite(const glm::mat4& perspective, float epsilon = kInfiniteEpsilon);

// ---- z-pass or z-fail ------------------------------------------------------------------------------
// The near-plane rectangle of a camera, in world space (corners in order around it).
struct NearRect {
  glm::vec3 corners[4];
};
NearRect nearRect(const glm::mat4& view, float fovY, float aspect, float nearZ);
// Can the shadow volume of a caster in `bounds` reach the near rectangle? Then some near-plane pixel
// starts inside the volume and z-pass miscounts it: use z-fail. The volume reaches a near point Q
// only if the segment from Q to the light (a ray for a directional light) hits the caster, i.e. the
// caster meets the convex hull of the rectangle and the light. Conservative: a box that is not wholly
// outside one plane of that hull counts as meeting it. World space.
bool volumeMayReachNearPlane(const Aabb& bounds, const NearRect& near, const glm::vec4& light);

// ---- Stencil operations ------------------------------------------------------------------------------
enum class StencilOp { Keep, IncrWrap, DecrWrap };
// What glStencilOpSeparate(face, sfail, dpfail, dppass) gets for one face orientation.
struct FaceStencilOps {
  StencilOp stencilFail = StencilOp::Keep, depthFail = StencilOp::Keep, depthPass = StencilOp::Keep;
  bool operator==(const FaceStencilOps&) const = default;
};
struct StencilOps {
  FaceStencilOps front, back;
  bool operator==(const StencilOps&) const = default;
};
// z-pass (the lecture's): count the volume faces IN FRONT of the surface: front faces +1, back
// faces -1 where the depth test passes. z-fail (Carmack's reverse): count the faces BEHIND it:
// back faces +1, front faces -1 where it fails. Wrapping, so the order of faces does not matter.
StencilOps stencilOps(bool zFail);

// ---- Scissor -------------------------------------------------------------------------------------------
// Distance beyond which a light's attenuated intensity falls below `threshold` (same units as
// intensity): solves c0 + c1 d + c2 d^2 = intensity / threshold. Infinite (1e30) for a directional
// light or one that never falls that low (c1 = c2 = 0).
float lightReach(const Light& light, float threshold = 1.0f / 256.0f);
// Pixel rectangle (x, y from the bottom left, width, height) covering the sphere (centre, radius) on a
// width x height viewport: the projected corners of its bounding box, clamped. The whole viewport
// when part of the box is behind the near plane; empty (width 0) when it is wholly off screen.
struct ScissorRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const ScissorRect&) const = default;
};
ScissorRect scissorForSphere(const glm::vec3& centre, float radius, const glm::mat4& viewProj, int width, int height);

// Every caster's volume for one light, in world space, as a lesson draws them: per object its side
// triangles first, then its caps (z-pass draws only the sides; a mesh that is not closed gets no
// caps), and the silhouette edges (two world-space end points each) for the views.
struct SceneVolumes {
  std::vector<glm::vec4> triangles;     // w = 0: extruded to infinity
  std::vector<int> first, sides, caps;  // per object: first vertex, side and cap vertex counts
  std::vector<glm::vec3> silhouette;
};
// `lightWorld`: (position, 1) or (-direction, 0). `casts(o)` picks the casters (others get empty
// ranges, so indices stay per object).
void buildSceneVolumes(const Scene& scene, const std::vector<EdgeAdjacency>& adjacency, const glm::vec4& lightWorld,
                       const std::function<bool(std::size_t)>& casts, SilhouetteTest test, SceneVolumes& out);

}  // namespace shadowlab::volume

#pragma once
// The maths of shadow maps, GL-free so it is unit-tested and graded on a machine with no GPU
// (lessons 02 and 03). The shaders in shaders/02_shadow_maps and shaders/03_shadow_quality mirror
// these functions; keep the two in step.
//
// Conventions: GLM column vectors, right-handed, GL clip space ([-1,1]^3 after the divide).
// Shadow-map texture space is [0,1]^3 ([Boreskov2005]: translate(0.5) * scale(0.5) * P_light * V_light).
// A depth map's row 0 is v = 0, the way GL stores a depth texture rendered from the light (its
// bottom row, NDC y = -1, is row 0).
#include <array>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"

namespace shadowlab::shadow {

// ---- lesson 02: the texture matrix and the depth comparison ---------------------------------------

// translate(0.5) * scale(0.5) * P_light * V_light ([Boreskov2005]): world -> shadow-map [0,1]^3.
glm::mat4 textureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView);
// The shadow-map coordinates (u, v, depth) of a world point: textureMatrix * (p, 1), divided by w.
glm::vec3 shadowCoord(const glm::mat4& textureMatrix, const glm::vec3& worldPoint);

// The depth comparison of ARB_shadow with GL_LEQUAL: lit (1) when the fragment, moved toward the
// light by `bias`, is not farther than what the light saw: fragmentDepth - bias <= storedDepth.
float depthCompare(float fragmentDepth, float storedDepth, float bias);

// A depth map on the CPU: width * height depths in [0,1], row-major, row 0 at v = 0.
struct DepthMap {
  int width = 0, height = 0;
  std::vector<float> depth;
  DepthMap() = default;
  // Throws std::invalid_argument when a size is below 1 or depth.size() != width * height.
  DepthMap(int width, int height, std::vector<float> depth);
  DepthMap(int width, int height, float fill);
  // The texel (x, y), clamped to the edge (GL_CLAMP_TO_EDGE).
  float at(int x, int y) const;
};

// One hardware-style lookup, GL_NEAREST: the texel floor(u * width), floor(v * height) compared
// with depthCompare. Outside the map ([0,1]^2) or beyond the light's far plane (depth > 1) the light
// knows nothing: lit (1), like a border colour of 1.
float shadowLookup(const DepthMap& map, const glm::vec3& uvz, float bias);

// ---- lesson 03: quality --------------------------------------------------------------------------

// Slope-scaled bias: constant + slope * tan(theta), theta the angle between N and L (cosTheta =
// N.L), clamped to maxBias; a surface facing away or grazing (cosTheta <= 0) gets maxBias.
float slopeScaledBias(float constant, float slope, float cosTheta, float maxBias);

// Hardware 2x2 PCF (GL_LINEAR on a depth texture with compare mode): the four nearest texels'
// comparisons are blended with bilinear weights. texel = uv * size (continuous texel coordinates,
// texel centres at i + 0.5). Returns the weights of the texels (x0, y0), (x0+1, y0), (x0, y0+1),
// (x0+1, y0+1) with x0 = floor(texel.x - 0.5), y0 = floor(texel.y - 0.5). They sum to 1.
glm::vec4 bilinearPcfWeights(const glm::vec2& texel);
// The same filter on a CPU map: sum of weights * depthCompare of the four texels.
float bilinearPcfLookup(const DepthMap& map, const glm::vec3& uvz, float bias);
// N x N box PCF of nearest comparisons centred on the texel under uvz (n odd, >= 1): the share of
// lit taps. Throws std::invalid_argument for an even or non-positive n.
float boxPcfLookup(const DepthMap& map, const glm::vec3& uvz, float bias, int n);

// Cube maps, in GL's face order 0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z, 5 -Z. The face a lookup vector picks:
// its major axis (ties go to x before y before z, as the GL tables read); -1 for the zero vector.
int cubeFace(const glm::vec3& direction);
// (s, t) in [0,1]^2 on that face (GL 4.1 spec, table 3.19: sc, tc and ma per face).
glm::vec2 cubeFaceUv(const glm::vec3& direction);
// The view matrix that renders face `face` from `position` with a 90-degree perspective, so that
// the rendered image is what a samplerCube lookup reads there. Throws for a face outside 0..5.
glm::mat4 cubeFaceView(const glm::vec3& position, int face);
// The window depth [0,1] a 90-degree perspective(near, far) writes for a point at distance
// `majorAxis` along the face's axis: what samplerCubeShadow compares against.
float cubeDepth(float majorAxis, float nearZ, float farZ);

// A convex volume (a frustum or a box): inward planes dot(n, p) + w >= 0 and its 8 corners, corner
// i at (x = i&1, y = i&2, z = i&4 ? high : low) in the NDC cube of `viewProj` (or the box).
struct ConvexVolume {
  std::array<glm::vec4, 6> planes{};  // xyz unit inward normal, w offset
  std::array<glm::vec3, 8> corners{};
};
// The volume `viewProj` maps onto [-1,1]^3. Throws std::invalid_argument for a singular matrix.
ConvexVolume volumeFromViewProj(const glm::mat4& viewProj);
// An axis-aligned box as a volume. Throws std::invalid_argument for an empty box.
ConvexVolume volumeFromBox(const Aabb& box);
// Conservative overlap: false only when a plane of one volume has every corner of the other
// outside (a separating plane). Used to skip cube faces that the view frustum misses.
bool volumesMayIntersect(const ConvexVolume& a, const ConvexVolume& b);
// The vertices of a ∩ b (each face polygon of one clipped by the other's planes); empty when they
// miss. Used to find the receivers the view needs: the scene bounds inside the view frustum.
std::vector<glm::vec3> intersectionPoints(const ConvexVolume& a, const ConvexVolume& b);

// View culling in clip space: true when every corner of `box` lies outside one and the same of
// the six planes -w <= x, y, z <= w of `viewProj` (linear in homogeneous coordinates, so exact for
// corners behind the eye too). Such a box draws no fragment; false may still draw none. An empty
// box is outside.
bool boxOutsideClip(const glm::mat4& viewProj, const Aabb& box);

// Caster culling against the light volume swept from the view frustum toward the light
// (directional light travelling along lightDirection): a caster can shade something in the view
// only if the box swept along lightDirection reaches the volume. False when some plane has the box
// outside and the sweep moves away from it or along it (dot(n, lightDirection) <= 0).
bool casterMayShadow(const Aabb& caster, const ConvexVolume& view, const glm::vec3& lightDirection);

// Texel snapping of an orthographic box (centre, half extents in light space) for a map of
// mapSize texels a side: the box made square with half side h = max(half.x, half.y, 1e-3) times
// (1 + 2 / mapSize) (a texel of room each side for the centre's move), h rounded UP to a multiple of
// step = 2^ceil(log2 h) / 4 (so h changes only when the extent crosses a step), and the centre
// rounded to the nearest multiple of the texel 2 h / mapSize: the map's texels stay put in the world
// while the camera moves, and an edge does not crawl.
struct TexelSnap {
  glm::vec2 centre{0.0f};
  float half = 0.0f;
};
TexelSnap snapToTexels(const glm::vec2& centre, const glm::vec2& half, int mapSize);
// A replacement for snapToTexels (a student's, lesson 10's exercise 10.2); empty: the reference.
using TexelSnapper = std::function<TexelSnap(const glm::vec2&, const glm::vec2&, int)>;

// The light camera of a directional light, fitted to what the view needs (lesson 03).
struct OrthoFit {
  glm::mat4 view{1.0f}, projection{1.0f};
  glm::vec3 lightMin{0.0f}, lightMax{0.0f};  // the fitted box in light view space
  float texelWorld = 0.0f;                   // world size of one texel across the map
};
// Light view: from the world origin looking along lightDirection with a fixed up vector, so the
// texel grid does not turn with the camera. x, y: the bounds of `receivers` in light space; z:
// from the receivers' far side to the nearest caster toward the light (casters only extend the
// near side). With `snap`, the half size is rounded up to a quarter of its power of two and the
// centre to whole texels, so a moving camera moves the grid by whole texels (no shimmer). Throws
// std::invalid_argument for no receivers, a zero direction or mapSize < 1. snapper: see TexelSnapper.
OrthoFit fitOrthographic(const glm::vec3& lightDirection, std::span<const glm::vec3> receivers,
                         std::span<const Aabb> casters, int mapSize, bool snap, const TexelSnapper& snapper = {});

// A look-at for a light direction with a fixed up vector (y, or x when the light is near vertical).
glm::mat4 lightViewAlong(const glm::vec3& eye, const glm::vec3& direction);

// The Poisson disk used by lesson 03's PCF (16 points in the unit disk, fixed; mirrored in the
// shader), and the per-pixel rotation angle in [0, 2 pi) from a hash of the pixel.
std::span<const glm::vec2> poissonDisk();
float rotationAngle(const glm::vec2& pixel);

}  // namespace shadowlab::shadow

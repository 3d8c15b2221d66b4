#pragma once
// The maths of soft shadows (lesson 05), GL-free so it is unit-tested and graded without a GPU.
// The shaders in shaders/05_soft_shadows/shadow_{many,pcss,single_sample,light_mesh,filterable}.frag and
// soft_maps.glsl mirror these functions; keep the two in step.
//
// The emitter is a sphere of radius R (Light::area = Sphere, Light::radius). From a point that sees
// it at distance D it is a disk of angular radius ~ R / D; a straight occluding edge across that
// disk leaves the part from -R to a visible (Tarantsev's lecture 12 after Rogers):
//   penumbra half-width   r = d / (n.L) * R / D            (d: caster point to the centre line)
//   visible fraction      A_frac(a/R) = 1/2 + (1/pi) [ (a/R) sqrt(1 - (a/R)^2) + asin(a/R) ]
//   linear approximation  (1 + a/R) / 2
// Light-space conventions of the soft map techniques: a perspective camera at the sphere's centre
// looking along the light's axis, depth z = distance along the axis (positive), uv in [0,1]^2 with
// tanHalfFov the tangent of half the field of view: a point at view-space (x, y, -z) has
// u = 0.5 + x / (2 z tanHalfFov).
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/light.hpp"
#include "core/mesh.hpp"

namespace shadowlab::soft {

// ---- the spherical light's penumbra -------------------------------------------------------------

// The solid angle of a sphere of radius R at distance D, as the lecture writes it (small angles):
// pi (R / D)^2. Throws std::invalid_argument for R < 0 or D <= 0.
float sphereSolidAngle(float R, float D);
// r = d / (n.L) * R / D: the half-width of the penumbra on the receiver, measured across the
// shadow of the edge. Exact for an edge perpendicular to the plane of incidence (the plane of L and
// the receiver's normal); for other edges the factor 1 / (n.L) over-states the stretch. Throws
// std::invalid_argument for d < 0, R < 0, D <= 0 or nDotL <= 0 (a receiver facing away has none).
float penumbraHalfWidth(float d, float nDotL, float R, float D);
// The same from the solid angle the light subtends at the caster point: d / (n.L) sqrt(dw / pi).
float penumbraHalfWidthFromSolidAngle(float d, float nDotL, float solidAngle);

// The penumbra a caster point throws on a plane (n, w: dot(n, p) + w = 0, n unit, facing the light).
struct PenumbraPoint {
  bool valid = false;      // false when the ray from the light's centre misses the plane
  glm::vec3 centre{0.0f};  // where the ray from the light's centre through the caster point lands
  float d = 0, D = 0;      // caster point to centre; caster point to the light's centre
  float nDotL = 0;         // the plane's normal against the direction to the light at `centre`
  float halfWidth = 0;     // r
};
PenumbraPoint penumbraOnPlane(const glm::vec3& lightCentre, float R, const glm::vec3& casterPoint,
                              const glm::vec4& plane);

// The predicted penumbra of a caster edge a-b over a plane, `samples` points along the edge (>= 2):
// the centre line and the inner (umbra side) and outer edges, r either side across the edge's
// shadow within the plane. `casterInterior`: a point inside the caster; its shadow tells which side
// is the umbra. Points whose ray misses the plane are left out. `halfWidth` replaces
// penumbraHalfWidth(d, n.L, R, D) (a student's, impl=student).
struct PenumbraEdgeSample {
  glm::vec3 centre{0.0f}, inner{0.0f}, outer{0.0f};
  float halfWidth = 0;
};
using HalfWidthFn = std::function<float(float d, float nDotL, float R, float D)>;
std::vector<PenumbraEdgeSample> penumbraAlongEdge(const glm::vec3& lightCentre, float R, const glm::vec3& a,
                                                  const glm::vec3& b, const glm::vec3& casterInterior,
                                                  const glm::vec4& plane, int samples,
                                                  const HalfWidthFn& halfWidth = {});

// The 12 edges of a box (a unit cube [-1,1]^3 scaled by `half` and placed by `model`): a caster
// edge the lesson's overlay picks. Order: 4 along x, 4 along y, 4 along z.
std::array<std::array<glm::vec3, 2>, 12> boxEdges(const glm::mat4& model, const glm::vec3& half);

// ---- the visible fraction of the sphere ---------------------------------------------------------

// t = a / R, clamped to [-1, 1]: 0 nothing visible, 1 all of it.
float visibleFraction(float t);
float visibleFractionLinear(float t);
// t with visibleFraction(t) = v (v clamped to [0, 1]), by bisection to 1e-6.
float visibleFractionInverse(float v);

// How far the linear approximation is from A_frac, over `samples` evenly spaced t in [-1, 1]:
// the largest absolute difference (in units of full visibility) and where, and the largest
// difference relative to A_frac among the t where A_frac >= relativeFloor.
struct ApproximationError {
  double maxAbs = 0, maxAbsAt = 0;
  double maxRelative = 0, maxRelativeAt = 0;
};
ApproximationError linearApproximationError(int samples, double relativeFloor);

// The penumbra's profile a single-sample method shades with.
enum class Profile { Exact, Linear };
float profile(Profile p, float t);  // visibleFraction or visibleFractionLinear

// ---- percentage-closer soft shadows (Fernando 2005) -------------------------------------------

// The penumbra width estimate w = (d_receiver - d_blocker) / d_blocker * lightSize: with the light's
// radius for lightSize it is the half-width r at the receiver, measured across the rays. 0 when the
// blocker is not in front of the receiver. Throws std::invalid_argument for dBlocker <= 0 or lightSize < 0.
float pcssPenumbraWidth(float dReceiver, float dBlocker, float lightSize);
// The filter radius in map uv that reproduces that penumbra: w / (2 zReceiver tanHalfFov).
float pcssFilterRadiusUv(float R, float zReceiver, float zBlocker, float tanHalfFov);
// The blocker search region's radius in uv: where in the map, around the receiver's uv, something
// between the receiver and the light can hide part of the sphere (largest at the near plane):
// R (zReceiver - zNear) / (2 tanHalfFov zNear zReceiver), capped at maxUv.
float pcssSearchRadiusUv(float R, float zReceiver, float zNear, float tanHalfFov, float maxUv);
// The blocker search: the mean depth of the taps nearer than zReceiver - bias.
struct BlockerSearch {
  int blockers = 0;
  float meanDepth = 0;  // 0 when there is no blocker
};
BlockerSearch averageBlockerDepth(std::span<const float> tapDepths, float zReceiver, float bias);

// ---- Poisson taps, rotated per pixel ------------------------------------------------------------

// `count` points in the unit disk no two closer than the radius the count allows (dart throwing
// with a shrinking radius; best candidate of 30 per point), deterministic for a seed. count 1: the
// centre. Throws std::invalid_argument for count < 1 or > 256.
std::vector<glm::vec2> poissonDisk(int count, std::uint64_t seed = 1);
// A search shared by the four pixels of a 2x2 quad (PCSS's quad search, shadow_pcss.frag): count / 4
// points whose four quarter turns together are `count` points spread like poissonDisk's (best
// candidate against every quarter turn of the points so far and against its own). Each pixel of the
// quad reads the base points turned by its own quarter turn. Throws std::invalid_argument unless
// count is a multiple of 4 in 4..256.
std::vector<glm::vec2> quarterTurnDisk(int count, std::uint64_t seed = 1);
// The four quarter turns of every point, in the order the quad's pixels take them (turn j of all
// points, then turn j + 1): the taps a whole quad reads.
std::vector<glm::vec2> quarterTurns(std::span<const glm::vec2> base);
// The tap turned by `angle` radians (counter-clockwise): what each pixel does with its own angle
// (shadow::rotationAngle) so the taps' pattern becomes noise instead of banding.
glm::vec2 rotateTap(const glm::vec2& tap, float angle);
float smallestDistance(std::span<const glm::vec2> points);

// ---- single-sample soft shadows ----------------------------------------------------------------

// Parker et al. 1998 (an outer hull around each caster): a lit point whose ray to the light's centre
// passes `delta` from the caster, inside a hull of thickness `width` there, gets
// profile(2 delta / width - 1): 0 at the caster (the hard shadow's edge), 1 at the hull. The hard
// shadow stays black: no inner penumbra. width <= 0: 1 (no hull).
float outerPenumbra(float delta, float width, Profile p);
// The hull's thickness at a blocker that the light cone from a receiver needs: the cone's radius
// there, R * (distance receiver to blocker) / (distance receiver to light).
float lightConeRadius(float R, float receiverToBlocker, float receiverToLight);
// Haines 2001 (soft planar shadows with plateaus): on a planar receiver, at `distance` from the hard
// shadow's edge (outside), from a caster point whose penumbra half-width there is r: the plateau
// rises over the full penumbra width 2r, profile(distance / r - 1).
float plateau(float distance, float halfWidth, Profile p);

// ---- the light mesh: visibility on a regular 3D grid ------------------------------------------

struct LightGrid {
  glm::vec3 origin{0.0f};         // node (0, 0, 0)
  glm::vec3 step{1.0f};           // spacing along x, y, z
  glm::ivec3 nodes{2};            // count along x, y, z (each >= 2)
  std::vector<float> visibility;  // per node, x fastest; empty until filled
  std::size_t count() const { return std::size_t(nodes.x) * nodes.y * nodes.z; }
  std::size_t index(const glm::ivec3& n) const { return (std::size_t(n.z) * nodes.y + n.y) * nodes.x + n.x; }
  glm::vec3 node(const glm::ivec3& n) const { return origin + step * glm::vec3(n); }
};
// Nodes over `bounds` with one spacing on every axis: `nodesAlongLongest` along the longest side,
// as many as cover the others (at least 2), the grid centred on the box. A surface on the bounds
// (the ground) then has nodes in it: the shader looks up a little above surfaces (along N).
// Throws std::invalid_argument for an empty box or fewer than 2 nodes.
LightGrid makeLightGrid(const Aabb& bounds, int nodesAlongLongest);
// The 8 nodes around p (clamped to the grid) with their trilinear weights (summing to 1).
struct TrilinearTaps {
  std::array<glm::ivec3, 8> nodes{};
  std::array<float, 8> weights{};
};
TrilinearTaps trilinearTaps(const LightGrid& grid, const glm::vec3& p);
// The light mesh's visibility at p: the trilinear average of its nearest nodes. Throws
// std::invalid_argument when the grid holds no visibility.
float lightMeshVisibility(const LightGrid& grid, const glm::vec3& p);

// ---- point lights on the sphere (many point lights) -------------------------------------------

// n stratified points in the unit disk: a sx x sy jittered grid (sx the largest divisor of n not
// above sqrt(n)) through Shirley and Chiu's concentric map; n = 1 is the centre. Throws for n < 1.
std::vector<glm::vec2> stratifiedDiskSamples(int n, std::uint64_t seed = 1);
// n points in the unit ball whose shadow from ANY direction is a uniform disk: radial density
// proportional to 1 / sqrt(1 - r^2) (its projection along any line is constant), directions on a
// spherical Fibonacci lattice, radii stratified. n = 1 is the centre. Throws for n < 1.
std::vector<glm::vec3> isotropicBallSamples(int n, std::uint64_t seed = 1);

// A point light seen as a spot whose cone holds `bounds` (its bounding sphere): axis toward the
// centre, outer half-angle asin(radius / distance) plus a margin, at most 1.45 rad (a 3-radian field
// of view). nullopt when the light is inside the sphere (no single frustum holds the scene).
std::optional<Light> spotCovering(const Light& point, const Aabb& bounds);

// The depth range a light camera (view looking down -z) needs for `bounds`: the nearest and farthest
// corner along the axis, 2 % margin, near at least minNear (a light inside the bounds). Depth
// precision lives in near / far; a perspective map of a small scene wastes it on a fixed 0.1..1000.
glm::vec2 depthRange(const glm::mat4& view, const Aabb& bounds, float minNear);
// The nearest any caster comes to a light camera (view looking down -z): the smallest distance
// along the axis of a corner of a box that casts (casts[i] != 0, same length as boxes), at least
// minNear; minNear when none casts. Nothing in a map from that camera is nearer: PCSS's blocker
// search sizes its region for a blocker there (pcssSearchRadiusUv), not on the near plane, which
// fits the whole scene and the sphere's radius (a light among the bounds: minNear itself).
float nearestCasterDepth(const glm::mat4& view, std::span<const Aabb> boxes, std::span<const char> casts,
                         float minNear);

}  // namespace shadowlab::soft

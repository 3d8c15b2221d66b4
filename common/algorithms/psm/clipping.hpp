#pragma once
// Convex clipping for unit-cube clipping ([Kozlov2004] §4.1): the vertices of the union over i of
// (B_i ∩ F), B_i a receiver bounding box and F the camera's view frustum. Allocation-free except
// for appending to a caller-owned vector, so a lesson can call it every frame.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"
#include "algorithms/psm/conventions.hpp"

namespace shadowlab::psm {

// Half-space dot(normal, p) + offset >= 0 (inside). normal is unit length.
struct Plane {
  glm::dvec3 normal{0.0, 0.0, 1.0};
  double offset = 0.0;
  double distance(const glm::dvec3& p) const { return glm::dot(normal, p) + offset; }
};

// A convex polytope as its inward half-spaces and its corners (enough for the polytopes here:
// frusta, boxes, pyramids).
struct Frustum {
  std::array<Plane, 6> planes{};        // left, right, bottom, top, near, far (inward)
  std::array<glm::dvec3, 8> corners{};  // NDC corner i -> (x = i&1, y = i&2, z = i&4 ? +1 : -1)
};

// The frustum of a camera's P*V (any projective matrix with a finite inverse). Planes come from
// the corners, not from the rows of the matrix (Gribb-Hartmann), so they stay accurate at
// Zf/Zn = 1e6.
Frustum frustumFromViewProj(const glm::dmat4& viewProj, const glm::dmat4& invViewProj);

// Throws std::invalid_argument naming the box when a bound is NaN/inf, min > max on an axis, or
// the box is a single point (zero size on every axis). Flat boxes (a terrain tile) are allowed.
void validateBox(const Aabb& box);

// Sutherland-Hodgman: clips the convex polygon in[0..n) by one half-space into out (capacity
// kMaxPolygon); returns the new vertex count.
inline constexpr int kMaxPolygon = 24;
int clipPolygon(const glm::dvec3* in, int n, const Plane& plane, glm::dvec3* out);

// Appends the vertices of box ∩ frustum to out (duplicates possible, none when they miss).
// Returns the number appended.
std::size_t clipBoxToFrustum(const Aabb& box, const Frustum& frustum, std::vector<glm::dvec3>& out);

// out = the vertices of the union over boxes of (box ∩ frustum), in world space (out is cleared
// first; its capacity is kept, so per-frame calls do not allocate once warm).
void receiverKeyPoints(std::span<const Aabb> boxes, const Frustum& frustum, std::vector<glm::dvec3>& out);

// post[i] = the post-projective image of world[i] (divided by w). Points must have w > 0, which
// holds for points inside the frustum; throws std::invalid_argument otherwise.
void toPostProjectivePoints(const glm::dmat4& viewProj, std::span<const glm::dvec3> world,
                            std::vector<glm::dvec3>& post);

}  // namespace shadowlab::psm

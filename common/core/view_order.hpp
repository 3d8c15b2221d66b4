#pragma once
// Front-to-back triangle orders of a mesh, precomputed for viewers in every direction. A mesh whose
// triangles hide one another many times over from any side (a crown of alpha-tested leaf cards,
// about 50 layers deep) drawn nearest first lets the depth test reject the hidden fragments before
// their shader runs, on a GPU and on llvmpipe alike (early depth test; an alpha test's discard
// delays only the depth write). Any order draws the same image under depth LESS (the nearest
// fragment wins), but for exact ties.
//   directions  the 26 of a 3x3x3 cube less its centre: every direction within 28 degrees of one
//   order d     the mesh's triangles by their centroid along direction d, the one nearest a viewer
//               far along d first (ties in the mesh's own order)
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"

namespace shadowlab {

std::span<const glm::vec3> viewOrderDirections();
// Every direction's order, one after the other: viewOrderDirections().size() permutations of the
// mesh's triangles (mesh.indices, three per triangle, whole triangles moved).
std::vector<std::uint32_t> viewOrders(const Mesh& mesh);
// The order for a viewer in direction `towardViewer` from the mesh (its own space, any length): the
// direction with the largest dot product; -1 for a zero or non-finite vector.
int viewOrderFor(const glm::vec3& towardViewer);
// Where a projection looks from, in world space, for a world-to-clip matrix: its centre of
// projection (x, y, z, 1) for a perspective one, or for a parallel one the unit direction toward
// the viewer (x, y, z, 0), the way clip depth falls. The point every ray of the projection meets:
// the null vector of its x, y and w rows.
glm::vec4 viewerOf(const glm::mat4& viewProj);

}  // namespace shadowlab

#pragma once
// What a Perspective Shadow Map is fitted to and what it draws, GL-free (Kozlov et al., "Perspective
// Shadow Maps: Care and Feeding", §4.1, and the original's virtual camera, §3):
//   receiverVolumes   the rough bounding volumes of the shadow RECEIVERS that unit-cube clipping
//                     intersects with the view frustum: a coarse height map over a terrain, boxes
//                     for the blocks of a city and along the walls of a room
//   mayShadowFrustum  the potential casters: a box that can throw a shadow into the view frustum
//                     for a light, point or directional (the casters the original slides its
//                     virtual camera back for, and the only ones any PSM map draws)
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/clipping.hpp"
#include "core/mesh.hpp"
#include "core/scene.hpp"

namespace shadowlab::psm {

// Every object that receives shadows as its world box, except the large ones (a side longer than
// the scene's largest side / tiles): their triangles are binned by centroid into cells about that
// wide, and each non-empty cell gives the box of its triangles. The union of the boxes holds every
// receiving triangle, so clipping them by the frustum loses no receiver. tiles <= 1: object boxes
// only. Throws std::invalid_argument for tiles above 256.
std::vector<Aabb> receiverVolumes(const Scene& scene, int tiles);

// False when some plane of `frustum` has the whole box outside while the light is inside it (a
// point light at (p, 1): on the inner side; a direction (-d, 0): travelling along the plane or
// into the outside): every light ray that reaches a point inside then stays inside that plane
// and cannot pass through the box. Conservative: never false for a box that can shade the view.
bool mayShadowFrustum(const Aabb& box, const Frustum& frustum, const glm::dvec4& light);

// out[i] = casts[i] && mayShadowFrustum(boxes[i], ...) (out is resized; no allocation once warm).
// Returns how many are kept.
int potentialCasters(std::span<const Aabb> boxes, std::span<const char> casts, const Frustum& frustum,
                     const glm::dvec4& light, std::vector<char>& out);

}  // namespace shadowlab::psm

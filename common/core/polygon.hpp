#pragma once
// Polygons into triangles: ear clipping on the polygon's plane (its Newell normal), so concave
// polygons come out covering exactly their area. Assimp 5.2.5's aiProcess_Triangulate (Debian 12)
// clipped an ear across the notch of a concave pentagon (area 5 for a polygon of area 3) and
// tinyobjloader 2.0.0rc10 lost triangles; core/model_file triangulates with this instead.
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// Corner indices (into `corners`), three per triangle, each wound as the polygon is. Repeated and
// collinear corners are dropped; a polygon with no area gives no triangles. Throws
// std::invalid_argument("... crosses itself ...") for a polygon whose outline crosses itself.
std::vector<std::array<std::uint32_t, 3>> triangulatePolygon(std::span<const glm::vec3> corners);

}  // namespace shadowlab

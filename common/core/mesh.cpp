#include "core/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <glm/gtc/matrix_inverse.hpp>

namespace shadowlab {

Aabb Mesh::bounds() const {
  Aabb box;
  for (const glm::vec3& p : positions) box.extend(p);
  return box;
}

void Mesh::append(const Mesh& other, const glm::mat4& model) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(model));
  // A mirroring transform turns counter-clockwise triangles clockwise; swapping two corners keeps
  // the appended faces front-facing, as the convention in mesh.hpp promises.
  const bool mirrored = glm::determinant(glm::mat3(model)) < 0.0f;

  positions.reserve(positions.size() + other.positions.size());
  normals.reserve(positions.capacity());
  uvs.reserve(positions.capacity());
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.push_back(glm::vec3(model * glm::vec4(other.positions[i], 1.0f)));
    glm::vec3 n = i < other.normals.size() ? normalMatrix * other.normals[i] : glm::vec3(0.0f);
    const float len = glm::length(n);
    // Zero-length normals stay zero rather than becoming NaN, so a later pass can repair them.
    normals.push_back(len > 0.0f ? n / len : n);
    uvs.push_back(i < other.uvs.size() ? other.uvs[i] : glm::vec2(0.0f));
  }
  indices.reserve(indices.size() + other.indices.size());
  for (std::size_t t = 0; t + 2 < other.indices.size(); t += 3) {
    const std::uint32_t a = base + other.indices[t];
    const std::uint32_t b = base + other.indices[t + 1];
    const std::uint32_t c = base + other.indices[t + 2];
    indices.push_back(a);
    indices.push_back(mirrored ? c : b);
    indices.push_back(mirrored ? b : c);
  }
}

namespace {

// Welds positions closer than epsilon: each position is hashed into a grid of epsilon-sized cells
// and compared against the representatives of the 27 surrounding cells, so two points just either
// side of a cell border still weld.
std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3>& positions, float epsilon) {
  std::vector<std::uint32_t> ids(positions.size());
  if (!(epsilon > 0.0f)) {
    // No tolerance: only bit-identical positions weld.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> exact;
    std::uint32_t next = 0;
    std::vector<glm::vec3> reps;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      std::uint32_t bits[3];
      std::memcpy(bits, &positions[i], sizeof bits);
      const std::uint64_t key =
          (std::uint64_t(bits[0]) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(bits[1]) * 0xC2B2AE3D27D4EB4Full) ^ bits[2];
      auto& bucket = exact[key];
      std::uint32_t found = UINT32_MAX;
      for (std::uint32_t r : bucket)
        if (reps[r] == positions[i]) found = r;
      if (found == UINT32_MAX) {
        found = next++;
        reps.push_back(positions[i]);
        bucket.push_back(found);
      }
      ids[i] = found;
    }
    return ids;
  }
  struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      // Unsigned: the products wrap instead of overflowing.
      return std::size_t(std::uint64_t(c.x) * 73856093ull) ^ std::size_t(std::uint64_t(c.y) * 19349663ull) ^
             std::size_t(std::uint64_t(c.z) * 83492791ull);
    }
  };
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> grid;
  grid.reserve(positions.size());
  std::vector<glm::vec3> reps;
  const float eps2 = epsilon * epsilon;
  // A coordinate / epsilon beyond 2^62 (a loaded model's 1e19, found by fuzzing) is clamped
  // before the conversion, which would be undefined: far points then share an edge cell, and the
  // distance test below still tells them apart.
  auto axisCell = [&](float v) { return std::int64_t(std::clamp(std::floor(double(v) / epsilon), -0x1p62, 0x1p62)); };
  auto cellOf = [&](const glm::vec3& p) { return Cell{axisCell(p.x), axisCell(p.y), axisCell(p.z)}; };
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    const Cell c = cellOf(p);
    std::uint32_t found = UINT32_MAX;
    for (int dz = -1; dz <= 1 && found == UINT32_MAX; ++dz)
      for (int dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
        for (int dx = -1; dx <= 1 && found == UINT32_MAX; ++dx) {
          auto it = grid.find(Cell{c.x + dx, c.y + dy, c.z + dz});
          if (it == grid.end()) continue;
          for (std::uint32_t r : it->second) {
            const glm::vec3 d = reps[r] - p;
            if (glm::dot(d, d) <= eps2) {
              found = r;
              break;
            }
          }
        }
    if (found == UINT32_MAX) {
      found = static_cast<std::uint32_t>(reps.size());
      reps.push_back(p);
      grid[c].push_back(found);
    }
    ids[i] = found;
  }
  return ids;
}

}  // namespace

Topology analyseTopology(const Mesh& mesh, float weldEpsilon) {
  const std::vector<std::uint32_t> weld = weldPositions(mesh.positions, weldEpsilon);
  // Each directed half-edge as (undirected key, direction); sorting groups the uses of an edge.
  std::vector<std::uint64_t> halfEdges;
  halfEdges.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::uint32_t v[3];
    bool valid = true;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t index = mesh.indices[t + k];
      valid = valid && index < weld.size();
      v[k] = valid ? weld[index] : 0;
    }
    // Triangles that collapse after welding bound no area and cannot close or open anything.
    if (!valid || v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      // Low bit: walked from the lower id to the higher one or back.
      halfEdges.push_back((lo << 33) | (hi << 1) | (a < b ? 0u : 1u));
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  Topology topo;
  for (std::size_t i = 0; i < halfEdges.size();) {
    const std::uint64_t key = halfEdges[i] >> 1;
    std::size_t forward = 0, backward = 0;
    while (i < halfEdges.size() && (halfEdges[i] >> 1) == key) {
      ((halfEdges[i] & 1u) ? backward : forward) += 1;
      ++i;
    }
    ++topo.edges;
    const std::size_t uses = forward + backward;
    if (uses == 1) ++topo.boundaryEdges;
    else if (uses > 2) ++topo.nonManifoldEdges;
    else if (forward != 1) ++topo.inconsistentEdges;
  }
  return topo;
}

}  // namespace shadowlab

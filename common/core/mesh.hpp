#pragma once
// Triangle meshes on the CPU, apart from any GPU buffer (common/gl uploads them).
// Conventions: right-handed, y up, counter-clockwise front faces, unit normals, one normal and one
// uv per position (seams duplicate positions).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

struct Aabb {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    if (!b.empty()) {
      extend(b.min);
      extend(b.max);
    }
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
};

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;  // three per triangle

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return indices.size() / 3; }
  Aabb bounds() const;
  // Appends `other` transformed by `model` (normals by its inverse transpose).
  void append(const Mesh& other, const glm::mat4& model = glm::mat4(1.0f));
};

// Topology checks used by tests and by lessons that need closed meshes (shadow volumes).
// Positions closer than `weldEpsilon` are the same vertex, so uv seams do not open a mesh.
struct Topology {
  std::size_t edges = 0;              // distinct undirected edges
  std::size_t boundaryEdges = 0;      // used by one triangle only
  std::size_t nonManifoldEdges = 0;   // used by three or more triangles
  std::size_t inconsistentEdges = 0;  // two triangles walking the edge the same way (flipped winding)
  bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && inconsistentEdges == 0; }
};
Topology analyseTopology(const Mesh& mesh, float weldEpsilon = 1e-5f);

}  // namespace shadowlab

#include "core/view_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace shadowlab {

std::span<const glm::vec3> viewOrderDirections() {
  static const std::array<glm::vec3, 26> directions = [] {
    std::array<glm::vec3, 26> d{};
    std::size_t n = 0;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z)
          if (x != 0 || y != 0 || z != 0) d[n++] = glm::normalize(glm::vec3(float(x), float(y), float(z)));
    return d;
  }();
  return directions;
}

std::vector<std::uint32_t> viewOrders(const Mesh& mesh) {
  const std::size_t triangles = mesh.triangleCount();
  std::vector<glm::vec3> centroid(triangles);
  for (std::size_t t = 0; t < triangles; ++t)
    centroid[t] = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                   mesh.positions[mesh.indices[3 * t + 2]]) /
                  3.0f;
  std::vector<std::uint32_t> orders;
  orders.reserve(viewOrderDirections().size() * triangles * 3);
  std::vector<std::uint32_t> order(triangles);
  std::vector<float> along(triangles);
  for (const glm::vec3& d : viewOrderDirections()) {
    for (std::size_t t = 0; t < triangles; ++t) along[t] = glm::dot(centroid[t], d);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return along[a] > along[b]; });
    for (const std::uint32_t t : order)
      for (int k = 0; k < 3; ++k) orders.push_back(mesh.indices[3 * t + std::size_t(k)]);
  }
  return orders;
}

int viewOrderFor(const glm::vec3& towardViewer) {
  const float length = glm::length(towardViewer);
  if (!(length > 0.0f) || !std::isfinite(length)) return -1;
  const auto directions = viewOrderDirections();
  int best = 0;
  float bestDot = -2.0f;
  for (std::size_t d = 0; d < directions.size(); ++d) {
    const float dot = glm::dot(directions[d], towardViewer / length);
    if (dot > bestDot) bestDot = dot, best = int(d);
  }
  return best;
}

glm::vec4 viewerOf(const glm::mat4& m) {
  // Rows x, y, w of the matrix (glm is column-major: m[c][r]); their null vector by cofactors.
  const glm::vec4 a(m[0][0], m[1][0], m[2][0], m[3][0]), b(m[0][1], m[1][1], m[2][1], m[3][1]),
      c(m[0][3], m[1][3], m[2][3], m[3][3]);
  const glm::vec4 n(
      glm::determinant(glm::mat3(glm::vec3(a.y, a.z, a.w), glm::vec3(b.y, b.z, b.w), glm::vec3(c.y, c.z, c.w))),
      -glm::determinant(glm::mat3(glm::vec3(a.x, a.z, a.w), glm::vec3(b.x, b.z, b.w), glm::vec3(c.x, c.z, c.w))),
      glm::determinant(glm::mat3(glm::vec3(a.x, a.y, a.w), glm::vec3(b.x, b.y, b.w), glm::vec3(c.x, c.y, c.w))),
      -glm::determinant(glm::mat3(glm::vec3(a.x, a.y, a.z), glm::vec3(b.x, b.y, b.z), glm::vec3(c.x, c.y, c.z))));
  const float length = glm::length(glm::vec3(n));
  if (std::abs(n.w) > 1e-6f * length) return glm::vec4(glm::vec3(n) / n.w, 1.0f);
  const glm::vec3 depthRow(m[0][2], m[1][2], m[2][2]);  // clip z grows away from the viewer
  const glm::vec3 d = glm::vec3(n) / length;
  return glm::vec4(glm::dot(d, depthRow) > 0.0f ? -d : d, 0.0f);
}

}  // namespace shadowlab

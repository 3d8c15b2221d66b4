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

}  // namespace shadowlab

#include <algorithm>
#include <cmath>
#include <set>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh_gen.hpp"
#include "core/view_order.hpp"

using namespace shadowlab;

namespace {
// n unit cards stacked along z at z = 0, 1, ..., n - 1, in a shuffled order.
Mesh stack(int n) {
  Mesh mesh;
  const Mesh card = makeCard(1.0f, 1.0f);
  for (int k = 0; k < n; ++k) mesh.append(card, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, float((k * 7) % n)}));
  return mesh;
}
float centroidAlong(const Mesh& mesh, const std::uint32_t* tri, const glm::vec3& d) {
  return glm::dot(mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]], d) / 3.0f;
}
}  // namespace

TEST_CASE("view orders: 26 directions, every direction of the sphere within 28 degrees of one") {
  const auto dirs = viewOrderDirections();
  REQUIRE(dirs.size() == 26);
  for (const auto& d : dirs) CHECK(glm::length(d) == doctest::Approx(1.0f));
  // A dense set of directions: the nearest of the 26 is within 28 degrees (the worst case is 27.6).
  float worst = 1.0f;
  for (int i = 0; i < 2000; ++i) {
    const float z = 1.0f - 2.0f * (float(i) + 0.5f) / 2000.0f, a = 2.399963f * float(i);
    const glm::vec3 v(std::sqrt(1.0f - z * z) * std::cos(a), std::sqrt(1.0f - z * z) * std::sin(a), z);
    const int k = viewOrderFor(v * 3.0f);
    REQUIRE(k >= 0);
    worst = std::min(worst, glm::dot(dirs[std::size_t(k)], v));
    for (const auto& d : dirs) CHECK(glm::dot(d, v) <= glm::dot(dirs[std::size_t(k)], v) + 1e-6f);
  }
  CHECK(worst > std::cos(glm::radians(28.0f)));
  CHECK(viewOrderFor(glm::vec3(0.0f)) == -1);
  CHECK(viewOrderFor(glm::vec3(NAN, 0.0f, 1.0f)) == -1);
  CHECK(dirs[std::size_t(viewOrderFor({0.0f, 0.0f, 5.0f}))] == glm::vec3(0, 0, 1));
}

TEST_CASE("view orders: each a permutation of whole triangles, nearest the viewer first") {
  const Mesh mesh = stack(9);
  const auto orders = viewOrders(mesh);
  const auto dirs = viewOrderDirections();
  REQUIRE(orders.size() == dirs.size() * mesh.indices.size());
  // The triangles as sets of corners: each order holds exactly the mesh's.
  std::multiset<std::array<std::uint32_t, 3>> original;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    original.insert({mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
  for (std::size_t d = 0; d < dirs.size(); ++d) {
    const std::uint32_t* o = orders.data() + d * mesh.indices.size();
    std::multiset<std::array<std::uint32_t, 3>> seen;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) seen.insert({o[3 * t], o[3 * t + 1], o[3 * t + 2]});
    CHECK(seen == original);
    for (std::size_t t = 1; t < mesh.triangleCount(); ++t)
      CHECK(centroidAlong(mesh, o + 3 * (t - 1), dirs[d]) >= centroidAlong(mesh, o + 3 * t, dirs[d]));
  }
  // From +z the card at z = 8 comes first, from -z the one at z = 0.
  const std::size_t plusZ = std::size_t(viewOrderFor({0, 0, 1})), minusZ = std::size_t(viewOrderFor({0, 0, -1}));
  CHECK(mesh.positions[orders[plusZ * mesh.indices.size()]].z == doctest::Approx(8.0f));
  CHECK(mesh.positions[orders[minusZ * mesh.indices.size()]].z == doctest::Approx(0.0f));
  // Control: the mesh's own order is not sorted from +z (the stack was shuffled).
  bool sorted = true;
  for (std::size_t t = 1; t < mesh.triangleCount(); ++t)
    sorted = sorted && centroidAlong(mesh, &mesh.indices[3 * (t - 1)], {0, 0, 1}) >=
                           centroidAlong(mesh, &mesh.indices[3 * t], {0, 0, 1});
  CHECK_FALSE(sorted);
  CHECK(viewOrders(Mesh{}).empty());
}

TEST_CASE("view orders: where a projection looks from") {
  const glm::vec3 eye(3.0f, 4.0f, -5.0f), target(0.5f, 1.0f, 2.0f);
  const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0, 1, 0));
  const glm::vec4 p = viewerOf(glm::perspective(0.9f, 1.5f, 0.5f, 80.0f) * view);
  CHECK(p.w == 1.0f);
  CHECK(glm::length(glm::vec3(p) - eye) < 1e-3f);
  // A parallel projection: the direction toward the viewer, against the view.
  const glm::vec4 d = viewerOf(glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 50.0f) * view);
  CHECK(d.w == 0.0f);
  CHECK(glm::dot(glm::vec3(d), glm::normalize(eye - target)) == doctest::Approx(1.0f).epsilon(1e-5));
  // An off-centre (oblique) frustum still has its centre at the eye.
  const glm::vec4 q = viewerOf(glm::frustum(-0.2f, 0.6f, -0.1f, 0.3f, 0.5f, 40.0f) * view);
  CHECK(glm::length(glm::vec3(q) - eye) < 1e-3f);
}

// Polygon triangulation (core/polygon), the cases the hand-written OBJ parser was tested on and the
// concave pentagon Assimp 5.2.5's aiProcess_Triangulate got wrong: triangles that cover exactly the
// polygon's area, wound as it is, and self-crossing outlines refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/polygon.hpp"

using namespace shadowlab;

namespace {

struct Cover {
  double area = 0;
  bool woundAsPolygon = true;
  std::size_t triangles = 0;
};

Cover cover(const std::vector<glm::vec3>& p, const glm::vec3& normal) {
  Cover c;
  for (const auto& t : triangulatePolygon(p)) {
    const glm::dvec3 n = glm::cross(glm::dvec3(p[t[1]] - p[t[0]]), glm::dvec3(p[t[2]] - p[t[0]]));
    c.area += 0.5 * glm::length(n);
    c.woundAsPolygon = c.woundAsPolygon && glm::dot(n, glm::dvec3(normal)) > 0;
    ++c.triangles;
  }
  return c;
}

std::vector<glm::vec3> rotated(std::vector<glm::vec3> p, std::size_t by) {
  std::rotate(p.begin(), p.begin() + std::ptrdiff_t(by % p.size()), p.end());
  return p;
}

}  // namespace

TEST_CASE("polygon: a concave pentagon (an arrow) away from the origin: 3 triangles of area 3, every rotation") {
  const std::vector<glm::vec3> arrow = {{2, 0, 0}, {4, 0, 0}, {4, 2, 0}, {3, 1, 0}, {2, 2, 0}};
  for (std::size_t r = 0; r < arrow.size(); ++r) {
    INFO("rotation " << r);
    const Cover c = cover(rotated(arrow, r), {0, 0, 1});
    // 3, or 2 where corner (3,1) becomes a straight corner of the rest (it lies on (2,0)-(4,2)).
    CHECK(c.triangles >= 2);
    CHECK(c.triangles <= 3);
    CHECK(c.area == doctest::Approx(3.0));  // the 2 x 2 square less the notch of 1
    CHECK(c.woundAsPolygon);
  }
  // The same outline far from the origin and clockwise (seen from +z): still exact, wound as given.
  std::vector<glm::vec3> far;
  for (auto it = arrow.rbegin(); it != arrow.rend(); ++it) far.push_back(*it + glm::vec3(1000, -500, 20));
  const Cover c = cover(far, {0, 0, -1});
  CHECK(c.area == doctest::Approx(3.0));
  CHECK(c.woundAsPolygon);
}

TEST_CASE("polygon: a dart quad in every rotation and both windings covers its area (8 - 2)") {
  const std::vector<glm::vec3> dart = {{10, 10, 5}, {14, 12, 5}, {10, 14, 5}, {11, 12, 5}};
  for (std::size_t r = 0; r < 4; ++r) {
    INFO("rotation " << r);
    const Cover c = cover(rotated(dart, r), {0, 0, 1});
    CHECK(c.triangles == 2);
    CHECK(c.area == doctest::Approx(6.0));
    CHECK(c.woundAsPolygon);
  }
  const std::vector<glm::vec3> reversed(dart.rbegin(), dart.rend());
  CHECK(cover(reversed, {0, 0, -1}).area == doctest::Approx(6.0));
}

TEST_CASE("polygon: convex polygons in any plane give n - 2 triangles, repeats and straight corners dropped") {
  const std::vector<glm::vec3> hexagon = {{101, 0, 50}, {102, 0, 50}, {103, 0, 51},
                                          {102, 0, 52}, {101, 0, 52}, {100, 0, 51}};
  const Cover h = cover(hexagon, {0, -1, 0});
  CHECK(h.triangles == 4);
  CHECK(h.area == doctest::Approx(4.0));
  CHECK(h.woundAsPolygon);
  // A square with a straight corner on one side and a repeated last corner: at most n - 2 = 3
  // triangles of the square's area (the repeat gives none).
  const Cover s = cover({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 2, 0}}, {0, 0, 1});
  CHECK(s.triangles >= 2);
  CHECK(s.triangles <= 3);
  CHECK(s.area == doctest::Approx(4.0));
  // No area at all: nothing (a quad whose corners repeat, the libFuzzer find of the old parser).
  CHECK(triangulatePolygon(std::vector<glm::vec3>{{1, 1, 1}, {1, 1, 1}, {2, 2, 2}, {2, 2, 2}}).empty());
  CHECK(triangulatePolygon(std::vector<glm::vec3>{{0, 0, 0}, {1, 1, 1}}).empty());
}

TEST_CASE("polygon: a pentagram winds twice and is refused, never fanned into overlapping triangles") {
  std::vector<glm::vec3> star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * 3.14159265358979 * (2 * i) / 5;
    star.emplace_back(float(std::cos(a)), float(std::sin(a)), 0.0f);
  }
  try {
    triangulatePolygon(star);
    FAIL("a pentagram was triangulated");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "a face with 5 corners crosses itself; triangulate it when exporting");
  }
}

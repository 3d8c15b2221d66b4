#include "core/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace shadowlab {
namespace {

// The corners on the plane of the Newell normal, counter-clockwise seen against it; false when the
// polygon has no area at all.
bool project(std::span<const glm::vec3> c, std::vector<glm::dvec2>& out) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const glm::dvec3 a = c[i], b = c[(i + 1) % c.size()];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double length = glm::length(n);
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  n /= length;
  const glm::dvec3 u =
      glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(n, u);
  out.clear();
  for (const glm::vec3& p : c) out.emplace_back(glm::dot(glm::dvec3(p), u), glm::dot(glm::dvec3(p), v));
  return true;
}

double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether p lies inside or on the triangle abc (counter-clockwise).
bool inside(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double eps) {
  return cross(a, b, p) >= -eps && cross(b, c, p) >= -eps && cross(c, a, p) >= -eps;
}

// Whether the outline winds around once (turning angles summing to 2 pi): a pentagram winds twice.
bool windsOnce(const std::vector<glm::dvec2>& p, const std::vector<std::uint32_t>& ring) {
  double total = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 in = p[ring[k]] - p[ring[(k + n - 1) % n]], out = p[ring[(k + 1) % n]] - p[ring[k]];
    total += std::atan2(in.x * out.y - in.y * out.x, glm::dot(in, out));
  }
  return n < 3 || std::abs(total - 2.0 * 3.14159265358979) < 0.5;
}

[[noreturn]] void crossesItself(std::size_t corners) {
  throw std::invalid_argument("a face with " + std::to_string(corners) +
                              " corners crosses itself; triangulate it when exporting");
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulatePolygon(std::span<const glm::vec3> corners) {
  std::vector<std::array<std::uint32_t, 3>> out;
  if (corners.size() < 3) return out;
  if (corners.size() == 3) return {{0, 1, 2}};
  std::vector<glm::dvec2> p;
  if (!project(corners, p)) return out;
  double scale = 0;
  for (const glm::dvec2& q : p) scale = std::max({scale, std::abs(q.x), std::abs(q.y)});
  const double eps = 1e-12 * std::max(scale * scale, 1e-30);
  std::vector<std::uint32_t> ring;  // the corners still on the outline, repeats and straight turns dropped
  for (std::uint32_t i = 0; i < corners.size(); ++i)
    if (p[i] != p[(i + corners.size() - 1) % corners.size()]) ring.push_back(i);
  if (!windsOnce(p, ring)) crossesItself(corners.size());
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    bool clipped = false;
    for (std::size_t k = 0; k < n && !clipped; ++k) {
      const std::uint32_t a = ring[(k + n - 1) % n], b = ring[k], c = ring[(k + 1) % n];
      const double turn = cross(p[a], p[b], p[c]);
      if (std::abs(turn) <= eps) {  // collinear: b turns nowhere
        ring.erase(ring.begin() + std::ptrdiff_t(k));
        clipped = true;
        break;
      }
      if (turn < 0) continue;  // reflex: not an ear
      bool empty = true;
      for (std::uint32_t q : ring)
        if (q != a && q != b && q != c && p[q] != p[a] && p[q] != p[b] && p[q] != p[c] &&
            inside(p[q], p[a], p[b], p[c], eps))
          empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      ring.erase(ring.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped) crossesItself(corners.size());
  }
  if (ring.size() == 3 && std::abs(cross(p[ring[0]], p[ring[1]], p[ring[2]])) > eps) {
    if (cross(p[ring[0]], p[ring[1]], p[ring[2]]) < 0) crossesItself(corners.size());
    out.push_back({ring[0], ring[1], ring[2]});
  }
  return out;
}

}  // namespace shadowlab

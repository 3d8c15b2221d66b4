#include "algorithms/psm/clipping.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadowlab::psm {

namespace {

Plane planeThrough(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& inside) {
  glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  n /= len;
  Plane p{n, -glm::dot(n, a)};
  if (p.distance(inside) < 0.0) p = Plane{-n, -p.offset};
  return p;
}

// Box faces as quads, counter-clockwise order not needed by the clipper (convex is enough).
void boxFaces(const glm::dvec3& lo, const glm::dvec3& hi, std::array<std::array<glm::dvec3, 4>, 6>& faces) {
  const glm::dvec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z},
                           {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}};
  static constexpr int idx[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) faces[f][k] = c[idx[f][k]];
}

}  // namespace

Frustum frustumFromViewProj(const glm::dmat4& viewProj, const glm::dmat4& invViewProj) {
  requireFinite(viewProj, "viewProj");
  requireFinite(invViewProj, "inverse(viewProj)");
  Frustum f;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 ndc((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
    const glm::dvec4 h = invViewProj * ndc;
    f.corners[i] = glm::dvec3(h) / h.w;
  }
  glm::dvec3 centre(0.0);
  for (const auto& c : f.corners) centre += c / 8.0;
  const auto& c = f.corners;
  f.planes[0] = planeThrough(c[0], c[2], c[4], centre);  // x = -1
  f.planes[1] = planeThrough(c[1], c[3], c[5], centre);  // x = +1
  f.planes[2] = planeThrough(c[0], c[1], c[4], centre);  // y = -1
  f.planes[3] = planeThrough(c[2], c[3], c[6], centre);  // y = +1
  // Near and far planes through their own four corners, exactly (they are tiny and huge).
  f.planes[4] = planeThrough(c[0], c[1], c[2], centre);
  f.planes[5] = planeThrough(c[4], c[5], c[6], centre);
  return f;
}

void validateBox(const Aabb& box) {
  const glm::dvec3 lo(box.min), hi(box.max);
  if (!isFinite(lo) || !isFinite(hi)) throw std::invalid_argument("receiver box bound is not finite");
  for (int a = 0; a < 3; ++a)
    if (lo[a] > hi[a])
      throw std::invalid_argument("receiver box has min > max on axis " + std::to_string(a) + " (min " +
                                  std::to_string(lo[a]) + ", max " + std::to_string(hi[a]) + ")");
  if (lo == hi) throw std::invalid_argument("receiver box has zero size (a single point)");
}

int clipPolygon(const glm::dvec3* in, int n, const Plane& plane, glm::dvec3* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3& a = in[i];
    const glm::dvec3& b = in[(i + 1) % n];
    const double da = plane.distance(a), db = plane.distance(b);
    if (da >= 0.0 && m < kMaxPolygon) out[m++] = a;
    if ((da >= 0.0) != (db >= 0.0) && m < kMaxPolygon) {
      const double t = da / (da - db);
      out[m++] = a + t * (b - a);
    }
  }
  return m;
}

namespace {

// Per plane, the index of the box corner farthest along its normal (corner i: x = i&1, y = i&2,
// z = i&4 take the box's max); the nearest is 7 - that. The same for every box of a frustum.
struct FarCorners {
  int index[6];
  explicit FarCorners(const Frustum& f) {
    for (int k = 0; k < 6; ++k) {
      const glm::dvec3& n = f.planes[std::size_t(k)].normal;
      index[k] = (n.x >= 0 ? 1 : 0) | (n.y >= 0 ? 2 : 0) | (n.z >= 0 ? 4 : 0);
    }
  }
};

std::size_t clipBox(const Aabb& box, const Frustum& frustum, const FarCorners& farCorner,
                    std::vector<glm::dvec3>& out) {
  const glm::dvec3 lo(box.min), hi(box.max);
  // The common case in three comparisons per axis; validateBox names what is wrong otherwise.
  const glm::dvec3 size = hi - lo;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(size.x >= 0.0 && size.x < inf && size.y >= 0.0 && size.y < inf && size.z >= 0.0 && size.z < inf) ||
      !(size.x > 0.0 || size.y > 0.0 || size.z > 0.0)) [[unlikely]]
    validateBox(box);
  const std::size_t before = out.size();
  // The corners first: each plane's farthest and nearest corner is one of them, picked by index
  // (FarCorners), not by a select per coordinate and plane.
  glm::dvec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = glm::dvec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
  // Per plane: every corner outside (reject), every corner inside (the plane cannot cut the box),
  // or it straddles. Only straddled planes cut: most boxes are wholly inside (their 8 corners),
  // and a box on the frustum's edge usually straddles one or two planes.
  int straddled[6], count = 0;
  for (int k = 0; k < 6; ++k) {
    const Plane& p = frustum.planes[std::size_t(k)];
    if (p.distance(c[farCorner.index[k]]) < 0.0) return 0;
    if (p.distance(c[7 - farCorner.index[k]]) < 0.0) straddled[count++] = k;
  }
  if (count == 0) {
    out.insert(out.end(), c, c + 8);
    return 8;
  }
  // Vertices of B ∩ F lie on a face of B or a face of F: clip B's faces by the straddled planes of
  // F, and the straddled faces of F by B's planes (a vertex on an F face that is interior to B's
  // faces, e.g. a frustum corner inside the box, comes from the second pass).
  glm::dvec3 bufA[kMaxPolygon], bufB[kMaxPolygon];
  std::array<std::array<glm::dvec3, 4>, 6> faces;
  boxFaces(lo, hi, faces);
  for (const auto& face : faces) {
    int n = 4;
    for (int k = 0; k < 4; ++k) bufA[k] = face[k];
    glm::dvec3* cur = bufA;
    glm::dvec3* nxt = bufB;
    for (int k = 0; k < count && n > 0; ++k) {
      n = clipPolygon(cur, n, frustum.planes[std::size_t(straddled[k])], nxt);
      std::swap(cur, nxt);
    }
    out.insert(out.end(), cur, cur + n);
  }
  const Plane boxPlanes[6] = {{{1, 0, 0}, -lo.x}, {{-1, 0, 0}, hi.x}, {{0, 1, 0}, -lo.y},
                              {{0, -1, 0}, hi.y}, {{0, 0, 1}, -lo.z}, {{0, 0, -1}, hi.z}};
  // Frustum face of each plane (left, right, bottom, top, near, far), by corner index.
  static constexpr int fidx[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (int k = 0; k < count; ++k) {
    int n = 4;
    for (int c = 0; c < 4; ++c) bufA[c] = frustum.corners[std::size_t(fidx[straddled[k]][c])];
    glm::dvec3* cur = bufA;
    glm::dvec3* nxt = bufB;
    for (const Plane& p : boxPlanes) {
      n = clipPolygon(cur, n, p, nxt);
      std::swap(cur, nxt);
      if (n == 0) break;
    }
    out.insert(out.end(), cur, cur + n);
  }
  return out.size() - before;
}

}  // namespace

std::size_t clipBoxToFrustum(const Aabb& box, const Frustum& frustum, std::vector<glm::dvec3>& out) {
  return clipBox(box, frustum, FarCorners(frustum), out);
}

void receiverKeyPoints(std::span<const Aabb> boxes, const Frustum& frustum, std::vector<glm::dvec3>& out) {
  out.clear();
  const FarCorners farCorner(frustum);
  for (const Aabb& b : boxes) clipBox(b, frustum, farCorner, out);
}

void toPostProjectivePoints(const glm::dmat4& viewProj, std::span<const glm::dvec3> world,
                            std::vector<glm::dvec3>& post) {
  post.resize(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    const glm::dvec4 h = viewProj * glm::dvec4(world[i], 1.0);
    if (!(h.w > 0.0))
      throw std::invalid_argument("point " + std::to_string(i) + " has clip w = " + std::to_string(h.w) +
                                  " <= 0 (not in front of the camera)");
    post[i] = glm::dvec3(h) / h.w;
  }
}

}  // namespace shadowlab::psm

#include "algorithms/psm/texel_density.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "algorithms/psm/bias.hpp"
#include "core/scene.hpp"

namespace shadowlab::psm {

double rayTexelSpacing(const glm::dmat4& worldToClip, int side, const glm::dvec3& p, const glm::dvec3& dirFromLight) {
  const TexelStep t = texelStepFactors(worldToClip, glm::dvec2(double(side)));
  const glm::dvec4 d = t.u * glm::dot(t.r, glm::dvec4(p, 1.0));
  if (!(1.0 + d.w > 0.0)) return std::numeric_limits<double>::infinity();
  const glm::dvec3 step = (p + glm::dvec3(d)) / (1.0 + d.w) - p;
  const glm::dvec3 L = glm::normalize(dirFromLight);
  return glm::length(step - L * glm::dot(step, L));
}

namespace {

bool holds(const glm::dmat4& worldToClip, const glm::dvec3& p) {
  const glm::dvec4 h = worldToClip * glm::dvec4(p, 1.0);
  return h.w > 0.0 && std::abs(h.x) <= h.w * (1.0 + 1e-6) && std::abs(h.y) <= h.w * (1.0 + 1e-6);
}

}  // namespace

namespace {

// The ray's entry into the box (t, and the entered face's axis and sign), or from inside its exit.
struct BoxHit {
  double t = std::numeric_limits<double>::infinity();
  glm::dvec3 normal{0.0};
};
BoxHit rayEntry(const glm::dvec3& o, const glm::dvec3& d, const Aabb& b, double tMax) {
  double t0 = 0.0, t1 = tMax;
  int enter = -1, leave = -1;
  for (int a = 0; a < 3; ++a) {
    const double inv = 1.0 / d[a];
    double ta = (double(b.min[a]) - o[a]) * inv, tb = (double(b.max[a]) - o[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    if (ta > t0) t0 = ta, enter = a;
    if (tb < t1) t1 = tb, leave = a;
    if (!(t0 <= t1)) return {};
  }
  BoxHit h;
  const int axis = enter >= 0 ? enter : leave;  // from inside: where it leaves
  if (axis < 0) return {};                      // the whole ray inside: no face seen
  h.t = enter >= 0 ? t0 : t1;
  h.normal[axis] = d[axis] > 0.0 ? -1.0 : 1.0;  // facing the eye
  return h;
}

// A world point's map texel (x, y), or nothing behind the map's eye.
std::optional<glm::dvec2> texelOf(const glm::dmat4& worldToClip, int side, const glm::dvec3& p) {
  const glm::dvec4 h = worldToClip * glm::dvec4(p, 1.0);
  if (!(h.w > 0.0)) return std::nullopt;
  return (glm::dvec2(h) / h.w * 0.5 + 0.5) * double(side);
}

// Where the ray through NDC point `ndc` meets the plane (p, n), or nothing.
std::optional<glm::dvec3> throughPixel(const CameraFrustum& camera, const glm::dvec2& ndc, const glm::dvec3& eye,
                                       const glm::dvec3& p, const glm::dvec3& n) {
  const glm::dvec4 far = camera.invViewProj * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 d = glm::dvec3(far) / far.w - eye;
  const double dn = glm::dot(d, n);
  if (!(std::abs(dn) > 1e-12)) return std::nullopt;
  const double t = glm::dot(p - eye, n) / dn;
  if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
  return eye + d * t;
}

}  // namespace

namespace {
// The nearest t in (0, tMax) where o + t d meets triangle (a, b, c) (Moller and Trumbore 1997), or
// tMax; both sides count.
double rayTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                   const glm::dvec3& c, double tMax) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-18) return tMax;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return tMax;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return tMax;
  const double t = glm::dot(e2, q) * inv;
  return t > 0.0 && t < tMax ? t : tMax;
}
// The ray from the eye through the centre of cell (i, j) of a cols x rows grid over the screen: its
// unit direction and its length to the far plane.
std::pair<glm::dvec3, double> gridRay(const CameraFrustum& camera, const glm::dvec3& eye, int i, int j, int cols,
                                      int rows) {
  const glm::dvec2 ndc(2.0 * (i + 0.5) / cols - 1.0, 2.0 * (j + 0.5) / rows - 1.0);
  const glm::dvec4 far = camera.invViewProj * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 ray = glm::dvec3(far) / far.w - eye;
  const double length = glm::length(ray);
  return {ray / length, length};
}
}  // namespace

void screenSceneSamples(const CameraFrustum& camera, const Scene& scene, int cols, int rows,
                        std::vector<SurfaceSample>& out) {
  out.clear();
  struct Candidate {
    std::size_t object;
    glm::dmat4 model;
    Aabb box;
  };
  std::vector<Candidate> objects;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].receivesShadow)
      objects.push_back({i, glm::dmat4(scene.objects[i].model), scene.objectBounds(i)});
  const glm::dvec3 eye(glm::inverse(camera.view)[3]);
  std::vector<std::pair<double, std::size_t>> hits;  // (entry t, candidate)
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const auto [d, tMax] = gridRay(camera, eye, i, j, cols, rows);
      hits.clear();
      for (std::size_t k = 0; k < objects.size(); ++k) {
        Aabb grown = objects[k].box;  // a flat box (a ground quad) still has a face to enter
        grown.min -= glm::vec3(1e-4f);
        grown.max += glm::vec3(1e-4f);
        if (glm::all(glm::greaterThanEqual(glm::vec3(eye), grown.min)) &&
            glm::all(glm::lessThanEqual(glm::vec3(eye), grown.max)))
          hits.push_back({0.0, k});
        else if (const BoxHit h = rayEntry(eye, d, grown, tMax); std::isfinite(h.t)) hits.push_back({h.t, k});
      }
      std::sort(hits.begin(), hits.end());
      double best = tMax;
      glm::dvec3 normal(0.0);
      for (const auto& [entry, k] : hits) {
        if (entry >= best) break;  // every later box starts beyond the nearest triangle found
        const SceneObject& object = scene.objects[objects[k].object];
        const Mesh& mesh = scene.meshes[object.mesh];
        const bool twoSided = scene.materials[object.material].twoSided;  // else back faces are culled, as drawn
        const glm::dmat4& m = objects[k].model;
        const bool mirrored = glm::determinant(glm::dmat3(m)) < 0.0;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
          const glm::dvec3 a(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t]]), 1.0));
          const glm::dvec3 b(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + 1]]), 1.0));
          const glm::dvec3 c(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + 2]]), 1.0));
          const glm::dvec3 n = glm::cross(b - a, c - a) * (mirrored ? -1.0 : 1.0);
          if (!twoSided && glm::dot(n, d) >= 0.0) continue;  // seen from behind: not drawn (a camera inside a block)
          if (const double hit = rayTriangle(eye, d, a, b, c, best); hit < best) {
            best = hit;
            normal = glm::normalize(n);
          }
        }
      }
      if (best < tMax && glm::length(normal) > 0.5)
        out.push_back({eye + d * best, glm::dot(normal, d) > 0.0 ? -normal : normal});  // facing the eye
    }
}

void screenSurfaceSamples(const CameraFrustum& camera, std::span<const Aabb> receivers, int cols, int rows,
                          std::vector<SurfaceSample>& out) {
  out.clear();
  const glm::dvec3 eye(glm::inverse(camera.view)[3]);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const auto [d, tMax] = gridRay(camera, eye, i, j, cols, rows);
      BoxHit best;
      for (const Aabb& b : receivers)
        if (const BoxHit h = rayEntry(eye, d, b, tMax); h.t < best.t) best = h;
      if (std::isfinite(best.t)) out.push_back({eye + d * best.t, best.normal});
    }
}

double pixelAliasing(const CameraFrustum& camera, int pixelsHigh, const SurfaceSample& s, const glm::dmat4& worldToClip,
                     int side, double cap) {
  const double inf = std::numeric_limits<double>::infinity();
  const glm::dvec4 c = camera.viewProj * glm::dvec4(s.point, 1.0);
  if (!(c.w > 0.0) || pixelsHigh < 1) return inf;
  const glm::dvec2 ndc = glm::dvec2(c) / c.w;
  const glm::dvec2 pixel(2.0 / (camera.aspect * double(pixelsHigh)), 2.0 / double(pixelsHigh));  // in NDC
  const glm::dvec3 eye(glm::inverse(camera.view)[3]);
  const auto px = throughPixel(camera, ndc + glm::dvec2(pixel.x, 0.0), eye, s.point, s.normal);
  const auto py = throughPixel(camera, ndc + glm::dvec2(0.0, pixel.y), eye, s.point, s.normal);
  const auto t0 = texelOf(worldToClip, side, s.point);
  if (!px || !py || !t0) return inf;
  const auto tx = texelOf(worldToClip, side, *px), ty = texelOf(worldToClip, side, *py);
  if (!tx || !ty) return inf;
  // J's columns: texels per pixel along the screen's x and y; sigma_min from J^T J's smaller eigenvalue.
  const glm::dvec2 a = *tx - *t0, b = *ty - *t0;
  const double p = glm::dot(a, a), q = glm::dot(a, b), r = glm::dot(b, b);
  const double mid = 0.5 * (p + r), root = std::sqrt(std::max(0.0, 0.25 * (p - r) * (p - r) + q * q));
  const double sigmaMin = std::sqrt(std::max(0.0, mid - root));
  return sigmaMin > 0.0 ? std::min(1.0 / sigmaMin, cap) : cap;
}

TexelDensity predictAliasing(const CameraFrustum& camera, int pixelsHigh, std::span<const SurfaceSample> samples,
                             std::span<const glm::dmat4> maps, int side, const glm::dvec4& light) {
  TexelDensity out;
  double sum = 0.0;
  for (const SurfaceSample& s : samples) {
    const auto map = std::find_if(maps.begin(), maps.end(), [&](const glm::dmat4& m) { return holds(m, s.point); });
    if (map == maps.end()) continue;
    const double m = pixelAliasing(camera, pixelsHigh, s, *map, side);
    if (!std::isfinite(m)) continue;
    sum += m;
    ++out.points;
    const glm::dvec3 dir = light.w == 0.0 ? -glm::dvec3(light) : s.point - glm::dvec3(light) / light.w;
    if (glm::length(dir) > 0.0) out.maxSpacing = std::max(out.maxSpacing, rayTexelSpacing(*map, side, s.point, dir));
  }
  out.meanAliasing = out.points > 0 ? sum / out.points : 0.0;
  return out;
}

}  // namespace shadowlab::psm

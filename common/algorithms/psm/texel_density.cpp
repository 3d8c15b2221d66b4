#include "algorithms/psm/texel_density.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/psm/bias.hpp"

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

// The ray o + t d, t in [0, tMax), through the box: the middle of its entry and exit (a rough volume
// holds its surface somewhere between them: a height-map cell's top is not its ground; from the eye
// when the eye is inside it), +inf when it misses.
double rayMiddle(const glm::dvec3& o, const glm::dvec3& d, const Aabb& b, double tMax) {
  double t0 = 0.0, t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    const double inv = 1.0 / d[a];  // +-inf for an axis-parallel ray: the slab test still holds
    double ta = (double(b.min[a]) - o[a]) * inv, tb = (double(b.max[a]) - o[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (!(t0 <= t1)) return std::numeric_limits<double>::infinity();
  }
  return 0.5 * (t0 + t1);
}

}  // namespace

void screenSamples(const CameraFrustum& camera, std::span<const Aabb> receivers, int cols, int rows,
                   std::vector<glm::dvec3>& out) {
  out.clear();
  const glm::dvec3 eye(glm::inverse(camera.view)[3]);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const glm::dvec2 ndc(2.0 * (i + 0.5) / cols - 1.0, 2.0 * (j + 0.5) / rows - 1.0);
      const glm::dvec4 far = camera.invViewProj * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 ray = glm::dvec3(far) / far.w - eye;
      const double tMax = glm::length(ray);
      const glm::dvec3 d = ray / tMax;
      double best = std::numeric_limits<double>::infinity();
      for (const Aabb& b : receivers) best = std::min(best, rayMiddle(eye, d, b, tMax));
      if (std::isfinite(best)) out.push_back(eye + d * best);
    }
}

TexelDensity predictTexelDensity(const glm::dmat4& cameraView, std::span<const glm::dvec3> points,
                                 std::span<const glm::dmat4> maps, int side, const glm::dvec4& light) {
  TexelDensity out;
  double sum = 0.0;
  for (const glm::dvec3& p : points) {
    const double z = -(cameraView * glm::dvec4(p, 1.0)).z;
    if (!(z > 0.0)) continue;  // a key point on the eye's plane: no pixel size there
    const auto map = std::find_if(maps.begin(), maps.end(), [&](const glm::dmat4& m) { return holds(m, p); });
    if (map == maps.end()) continue;
    const glm::dvec3 dir = light.w == 0.0 ? -glm::dvec3(light) : p - glm::dvec3(light) / light.w;
    if (!(glm::length(dir) > 0.0)) continue;
    const double s = rayTexelSpacing(*map, side, p, dir);
    sum += s / z;
    out.maxSpacing = std::max(out.maxSpacing, s);
    ++out.points;
  }
  out.meanAliasing = out.points > 0 ? sum / out.points : 0.0;
  return out;
}

}  // namespace shadowlab::psm

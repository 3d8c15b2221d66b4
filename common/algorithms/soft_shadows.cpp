#include "algorithms/soft_shadows.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/mesh_gen.hpp"

namespace shadowlab::soft {
namespace {

constexpr float kPi = 3.14159265358979f;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

// ---- the spherical light's penumbra -------------------------------------------------------------

float sphereSolidAngle(float R, float D) {
  require(R >= 0 && D > 0,
          "sphereSolidAngle: R = " + std::to_string(R) + ", D = " + std::to_string(D) + " (need R >= 0, D > 0)");
  return kPi * (R / D) * (R / D);
}

float penumbraHalfWidth(float d, float nDotL, float R, float D) {
  require(d >= 0 && R >= 0 && D > 0 && nDotL > 0,
          "penumbraHalfWidth: d = " + std::to_string(d) + ", n.L = " + std::to_string(nDotL) +
              ", R = " + std::to_string(R) + ", D = " + std::to_string(D) + " (need d >= 0, n.L > 0, R >= 0, D > 0)");
  return d / nDotL * R / D;
}

float penumbraHalfWidthFromSolidAngle(float d, float nDotL, float solidAngle) {
  require(d >= 0 && nDotL > 0 && solidAngle >= 0, "penumbraHalfWidthFromSolidAngle: need d >= 0, n.L > 0, dw >= 0");
  return d / nDotL * std::sqrt(solidAngle / kPi);
}

PenumbraPoint penumbraOnPlane(const glm::vec3& light, float R, const glm::vec3& c, const glm::vec4& plane) {
  PenumbraPoint out;
  const glm::vec3 n(plane);
  const glm::vec3 toCaster = c - light;
  const float D = glm::length(toCaster);
  const float height = glm::dot(n, c) + plane.w;  // the caster point above the plane
  if (D <= 0 || height < 0) return out;
  const glm::vec3 dir = toCaster / D;
  const float down = glm::dot(n, dir);
  if (down >= -1e-6f) return out;  // the ray runs parallel to the plane or away from it
  out.d = -height / down;
  out.D = D;
  out.centre = c + dir * out.d;
  out.nDotL = -down;
  out.halfWidth = penumbraHalfWidth(out.d, out.nDotL, R, D);
  out.valid = true;
  return out;
}

std::vector<PenumbraEdgeSample> penumbraAlongEdge(const glm::vec3& light, float R, const glm::vec3& a,
                                                  const glm::vec3& b, const glm::vec3& interior, const glm::vec4& plane,
                                                  int samples, const HalfWidthFn& halfWidth) {
  require(samples >= 2, "penumbraAlongEdge: samples = " + std::to_string(samples) + " (need >= 2)");
  const PenumbraPoint pa = penumbraOnPlane(light, R, a, plane), pb = penumbraOnPlane(light, R, b, plane);
  const PenumbraPoint pi = penumbraOnPlane(light, R, interior, plane);
  std::vector<PenumbraEdgeSample> out;
  if (!pa.valid || !pb.valid) return out;
  const glm::vec3 n(plane);
  const glm::vec3 along = pb.centre - pa.centre;
  glm::vec3 across = glm::cross(n, along);
  if (glm::length(across) < 1e-6f) return out;  // the edge lies along a ray: its shadow is a point
  across = glm::normalize(across);
  if (pi.valid && glm::dot(pi.centre - pa.centre, across) < 0) across = -across;  // inner: toward the umbra
  for (int k = 0; k < samples; ++k) {
    const PenumbraPoint p = penumbraOnPlane(light, R, glm::mix(a, b, float(k) / float(samples - 1)), plane);
    if (!p.valid) continue;
    const float r = halfWidth ? halfWidth(p.d, p.nDotL, R, p.D) : p.halfWidth;
    out.push_back({p.centre, p.centre + across * r, p.centre - across * r, r});
  }
  return out;
}

std::array<std::array<glm::vec3, 2>, 12> boxEdges(const glm::mat4& model, const glm::vec3& half) {
  std::array<std::array<glm::vec3, 2>, 12> edges;
  auto corner = [&](glm::vec3 s) { return glm::vec3(model * glm::vec4(s * half, 1.0f)); };
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 4; ++k) {
      glm::vec3 lo(0.0f);
      lo[(axis + 1) % 3] = k & 1 ? 1.0f : -1.0f;
      lo[(axis + 2) % 3] = k & 2 ? 1.0f : -1.0f;
      glm::vec3 hi = lo;
      lo[axis] = -1.0f;
      hi[axis] = 1.0f;
      edges[std::size_t(axis * 4 + k)] = {corner(lo), corner(hi)};
    }
  return edges;
}

// ---- the visible fraction of the sphere ---------------------------------------------------------

float visibleFraction(float t) {
  t = std::clamp(t, -1.0f, 1.0f);
  return 0.5f + (t * std::sqrt(std::max(0.0f, 1.0f - t * t)) + std::asin(t)) / kPi;
}

float visibleFractionLinear(float t) { return 0.5f * (1.0f + std::clamp(t, -1.0f, 1.0f)); }

float visibleFractionInverse(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  float lo = -1.0f, hi = 1.0f;
  while (hi - lo > 1e-6f) {
    const float mid = 0.5f * (lo + hi);
    (visibleFraction(mid) < v ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

ApproximationError linearApproximationError(int samples, double floor) {
  require(samples >= 2, "linearApproximationError: samples = " + std::to_string(samples) + " (need >= 2)");
  ApproximationError e;
  for (int i = 0; i < samples; ++i) {
    const double t = -1.0 + 2.0 * i / (samples - 1);
    // In double: the float functions above would put their own rounding into the figure.
    const double exact = 0.5 + (t * std::sqrt(std::max(0.0, 1.0 - t * t)) + std::asin(t)) / 3.14159265358979323846;
    const double diff = std::abs(0.5 * (1.0 + t) - exact);
    if (diff > e.maxAbs) e = {diff, t, e.maxRelative, e.maxRelativeAt};
    if (exact >= floor && diff / exact > e.maxRelative) {
      e.maxRelative = diff / exact;
      e.maxRelativeAt = t;
    }
  }
  return e;
}

float profile(Profile p, float t) { return p == Profile::Exact ? visibleFraction(t) : visibleFractionLinear(t); }

// ---- percentage-closer soft shadows -------------------------------------------------------------

float pcssPenumbraWidth(float dReceiver, float dBlocker, float lightSize) {
  require(dBlocker > 0 && lightSize >= 0, "pcssPenumbraWidth: d_blocker = " + std::to_string(dBlocker) +
                                              ", light size = " + std::to_string(lightSize) +
                                              " (need d_blocker > 0, size >= 0)");
  return std::max(0.0f, (dReceiver - dBlocker) / dBlocker * lightSize);
}

float pcssFilterRadiusUv(float R, float zReceiver, float zBlocker, float tanHalfFov) {
  require(zReceiver > 0 && tanHalfFov > 0, "pcssFilterRadiusUv: need z_receiver > 0 and tan(fov/2) > 0");
  return pcssPenumbraWidth(zReceiver, zBlocker, R) / (2.0f * zReceiver * tanHalfFov);
}

float pcssSearchRadiusUv(float R, float zReceiver, float zNear, float tanHalfFov, float maxUv) {
  require(zReceiver > 0 && zNear > 0 && tanHalfFov > 0,
          "pcssSearchRadiusUv: need z_receiver > 0, z_near > 0, tan(fov/2) > 0");
  const float r = R * std::max(0.0f, zReceiver - zNear) / (2.0f * tanHalfFov * zNear * zReceiver);
  return std::min(r, maxUv);
}

BlockerSearch averageBlockerDepth(std::span<const float> taps, float zReceiver, float bias) {
  BlockerSearch s;
  double sum = 0;
  for (const float z : taps)
    if (z < zReceiver - bias) {
      ++s.blockers;
      sum += z;
    }
  if (s.blockers > 0) s.meanDepth = float(sum / s.blockers);
  return s;
}

// ---- Poisson taps -------------------------------------------------------------------------------

namespace {
glm::vec2 inUnitDisk(SplitMix64& rng) {
  const float r = std::sqrt(rng.uniform()), a = rng.uniform(0.0f, 2.0f * kPi);
  return glm::vec2(r * std::cos(a), r * std::sin(a));
}

// Mitchell's best candidate: of 30 uniform candidates, the one whose distance to the points so far
// (nearest(q)) is the largest.
template <class Nearest>
glm::vec2 bestCandidate(SplitMix64& rng, const Nearest& nearest) {
  glm::vec2 best(0.0f);
  float bestDistance = -1.0f;
  for (int c = 0; c < 30; ++c) {
    const glm::vec2 q = inUnitDisk(rng);
    const float d = nearest(q);
    if (d > bestDistance) {
      bestDistance = d;
      best = q;
    }
  }
  return best;
}

float nearestOf(const glm::vec2& q, std::span<const glm::vec2> points, float start) {
  for (const glm::vec2& p : points) start = std::min(start, glm::length(q - p));
  return start;
}
}  // namespace

std::vector<glm::vec2> poissonDisk(int count, std::uint64_t seed) {
  require(count >= 1 && count <= 256, "poissonDisk: count = " + std::to_string(count) + " (valid 1..256)");
  std::vector<glm::vec2> points{glm::vec2(0.0f)};
  if (count == 1) return points;
  points.clear();
  SplitMix64 rng(seed);
  points.push_back(inUnitDisk(rng));
  while (int(points.size()) < count)
    points.push_back(bestCandidate(rng, [&](const glm::vec2& q) { return nearestOf(q, points, 1e9f); }));
  return points;
}

std::vector<glm::vec2> quarterTurnDisk(int count, std::uint64_t seed) {
  require(count >= 4 && count <= 256 && count % 4 == 0,
          "quarterTurnDisk: count = " + std::to_string(count) + " (valid: a multiple of 4 in 4..256)");
  SplitMix64 rng(seed);
  std::vector<glm::vec2> base, all;  // all: every quarter turn of base, so it is closed under turns
  while (int(base.size()) < count / 4) {
    // The set of turns is symmetric, so a candidate's own turns are as far from it as the candidate
    // itself; its own quarter turn is |q| sqrt(2) away.
    base.push_back(
        bestCandidate(rng, [&](const glm::vec2& q) { return nearestOf(q, all, glm::length(q) * std::sqrt(2.0f)); }));
    for (const glm::vec2& t : quarterTurns(std::span<const glm::vec2>(&base.back(), 1))) all.push_back(t);
  }
  return base;
}

std::vector<glm::vec2> quarterTurns(std::span<const glm::vec2> base) {
  std::vector<glm::vec2> all;
  all.reserve(base.size() * 4);
  for (int turn = 0; turn < 4; ++turn)
    for (const glm::vec2& p : base) all.push_back(rotateTap(p, float(turn) * 0.5f * kPi));
  return all;
}

glm::vec2 rotateTap(const glm::vec2& tap, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return {c * tap.x - s * tap.y, s * tap.x + c * tap.y};
}

float smallestDistance(std::span<const glm::vec2> points) {
  float best = 1e30f;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) best = std::min(best, glm::length(points[i] - points[j]));
  return best;
}

// ---- single-sample soft shadows ----------------------------------------------------------------

float outerPenumbra(float delta, float width, Profile p) {
  if (width <= 0) return 1.0f;
  return profile(p, 2.0f * std::max(delta, 0.0f) / width - 1.0f);
}

float lightConeRadius(float R, float receiverToBlocker, float receiverToLight) {
  require(receiverToLight > 0,
          "lightConeRadius: receiver-to-light distance " + std::to_string(receiverToLight) + " (need > 0)");
  return R * std::clamp(receiverToBlocker / receiverToLight, 0.0f, 1.0f);
}

float plateau(float distance, float halfWidth, Profile p) {
  if (halfWidth <= 0) return 1.0f;
  return profile(p, std::max(distance, 0.0f) / halfWidth - 1.0f);
}

// ---- the light mesh ----------------------------------------------------------------------------

LightGrid makeLightGrid(const Aabb& bounds, int nodesAlongLongest) {
  require(!bounds.empty(), "makeLightGrid: empty bounds");
  require(nodesAlongLongest >= 2, "makeLightGrid: " + std::to_string(nodesAlongLongest) + " nodes (need >= 2)");
  const glm::vec3 extent = bounds.extent();
  const float longest = std::max({extent.x, extent.y, extent.z, 1e-6f});
  const float step = longest / float(nodesAlongLongest - 1);
  LightGrid g;
  for (int a = 0; a < 3; ++a) g.nodes[a] = std::max(2, int(std::ceil(extent[a] / step - 1e-4f)) + 1);
  g.step = glm::vec3(step);
  g.origin = bounds.center() - g.step * glm::vec3(g.nodes - 1) * 0.5f;
  return g;
}

TrilinearTaps trilinearTaps(const LightGrid& grid, const glm::vec3& p) {
  const glm::vec3 top = glm::vec3(grid.nodes - 1);
  const glm::vec3 g = glm::clamp((p - grid.origin) / grid.step, glm::vec3(0.0f), top);
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(g)), grid.nodes - 2);
  const glm::vec3 f = g - glm::vec3(i0);
  TrilinearTaps t;
  for (int k = 0; k < 8; ++k) {
    const glm::ivec3 o(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    t.nodes[std::size_t(k)] = i0 + o;
    t.weights[std::size_t(k)] = (o.x ? f.x : 1 - f.x) * (o.y ? f.y : 1 - f.y) * (o.z ? f.z : 1 - f.z);
  }
  return t;
}

float lightMeshVisibility(const LightGrid& grid, const glm::vec3& p) {
  require(grid.visibility.size() == grid.count(), "lightMeshVisibility: the grid holds " +
                                                      std::to_string(grid.visibility.size()) + " values for " +
                                                      std::to_string(grid.count()) + " nodes");
  const TrilinearTaps t = trilinearTaps(grid, p);
  float v = 0;
  for (int k = 0; k < 8; ++k) v += t.weights[std::size_t(k)] * grid.visibility[grid.index(t.nodes[std::size_t(k)])];
  return v;
}

// ---- point lights on the sphere -----------------------------------------------------------------

namespace {

int largestDivisorAtMostRoot(int n) {
  int best = 1;
  for (int d = 1; d * d <= n; ++d)
    if (n % d == 0) best = d;
  return best;
}

// Shirley and Chiu 1997: the square [0,1]^2 onto the unit disk, keeping strata compact.
glm::vec2 concentric(float u, float v) {
  const float a = 2 * u - 1, b = 2 * v - 1;
  if (a == 0 && b == 0) return glm::vec2(0.0f);
  float r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = 0.25f * kPi * b / a;
  } else {
    r = b;
    phi = 0.5f * kPi - 0.25f * kPi * a / b;
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// The radius whose share of the ball's weight 1 / sqrt(1 - r^2) is u: with r = sin(phi) the
// cumulative share is (2 phi - sin 2 phi) / pi.
float ballRadius(float u) {
  float lo = 0, hi = 0.5f * kPi;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    ((2 * mid - std::sin(2 * mid)) / kPi < u ? lo : hi) = mid;
  }
  return std::sin(0.5f * (lo + hi));
}

}  // namespace

std::vector<glm::vec2> stratifiedDiskSamples(int n, std::uint64_t seed) {
  require(n >= 1, "stratifiedDiskSamples: n = " + std::to_string(n) + " (need >= 1)");
  if (n == 1) return {glm::vec2(0.0f)};
  const int sx = largestDivisorAtMostRoot(n), sy = n / sx;
  SplitMix64 rng(seed);
  std::vector<glm::vec2> out;
  out.reserve(std::size_t(n));
  for (int j = 0; j < sy; ++j)
    for (int i = 0; i < sx; ++i) {
      const float u = (float(i) + rng.uniform()) / float(sx);
      const float v = (float(j) + rng.uniform()) / float(sy);
      out.push_back(concentric(u, v));
    }
  return out;
}

std::vector<glm::vec3> isotropicBallSamples(int n, std::uint64_t seed) {
  require(n >= 1, "isotropicBallSamples: n = " + std::to_string(n) + " (need >= 1)");
  if (n == 1) return {glm::vec3(0.0f)};
  SplitMix64 rng(seed);
  const float turn = rng.uniform(0.0f, 2.0f * kPi);
  // Radii strata visited in a golden-ratio order, so radius and direction are not correlated.
  int stride = std::max(1, int(std::lround(0.618034 * n)));
  while (std::gcd(stride, n) != 1) ++stride;
  std::vector<glm::vec3> out;
  out.reserve(std::size_t(n));
  for (int k = 0; k < n; ++k) {
    const float z = 1.0f - (2.0f * float(k) + 1.0f) / float(n);
    const float phi = turn + float(k) * 2.39996323f;  // the golden angle
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float u = (float((k * stride) % n) + rng.uniform()) / float(n);
    out.push_back(ballRadius(u) * glm::vec3(s * std::cos(phi), s * std::sin(phi), z));
  }
  return out;
}

std::optional<Light> spotCovering(const Light& point, const Aabb& bounds) {
  if (bounds.empty()) return std::nullopt;
  const glm::vec3 c = bounds.center();
  const float radius = 0.5f * glm::length(bounds.extent());
  const float distance = glm::length(c - point.position);
  if (distance <= radius * 1.001f) return std::nullopt;
  Light spot = point;
  spot.kind = LightKind::Spot;
  spot.direction = (c - point.position) / distance;
  spot.spotOuter = std::min(std::asin(radius / distance) + 0.02f, 1.45f);
  spot.spotInner = spot.spotOuter;
  return spot;
}

glm::vec2 depthRange(const glm::mat4& view, const Aabb& bounds, float minNear) {
  require(!bounds.empty() && minNear > 0, "depthRange: need bounds and minNear > 0");
  float lo = 1e30f, hi = -1e30f;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner(k & 1 ? bounds.max.x : bounds.min.x, k & 2 ? bounds.max.y : bounds.min.y,
                           k & 4 ? bounds.max.z : bounds.min.z);
    const float z = -(view * glm::vec4(corner, 1.0f)).z;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  const float nearZ = std::max(minNear, lo * 0.98f);
  return {nearZ, std::max(hi * 1.02f, nearZ + 0.1f)};
}

float nearestCasterDepth(const glm::mat4& view, std::span<const Aabb> boxes, std::span<const char> casts,
                         float minNear) {
  require(boxes.size() == casts.size() && minNear > 0, "nearestCasterDepth: boxes and casts differ, or minNear <= 0");
  float lo = 1e30f;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (!casts[i] || boxes[i].empty()) continue;
    for (int k = 0; k < 8; ++k) {
      const Aabb& b = boxes[i];
      const glm::vec3 corner(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z);
      lo = std::min(lo, -(view * glm::vec4(corner, 1.0f)).z);
    }
  }
  return lo > 1e29f ? minNear : std::max(minNear, lo);
}

}  // namespace shadowlab::soft

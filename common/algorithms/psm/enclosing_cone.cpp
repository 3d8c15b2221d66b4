#include "algorithms/psm/enclosing_cone.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/lanes.hpp"

namespace shadowlab::psm {

namespace {

struct Ball {
  glm::dvec3 c{0.0};
  double r2 = -1.0;  // squared radius; < 0: empty
};

// Relative slack: cones from a far light are ~1e-9 rad wide, so an absolute slack would swamp
// them; the measured half-angle afterwards makes containment exact anyway.
bool contains(const Ball& b, const glm::dvec3& p) {
  const glm::dvec3 d = p - b.c;
  return glm::dot(d, d) <= b.r2 * (1.0 + 1e-10) + 1e-30;
}

Ball ball2(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c = 0.5 * (a + b);
  const glm::dvec3 d = a - c;
  return {c, glm::dot(d, d)};
}

// Smallest ball with a, b, c on its boundary: the circumcircle's centre in their plane.
Ball ball3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a;
  const glm::dvec3 n = glm::cross(ab, ac);
  const double n2 = glm::dot(n, n);
  // Relative test (sin^2 of the angle at a): the cones of far lights are 1e-9 rad across, so
  // an absolute threshold would call every triangle degenerate.
  if (!(n2 > 1e-24 * glm::dot(ab, ab) * glm::dot(ac, ac))) {
    // Two of the points coincide: the ball over the farthest pair.
    Ball best = ball2(a, b);
    Ball alt = ball2(a, c);
    if (alt.r2 > best.r2) best = alt;
    alt = ball2(b, c);
    if (alt.r2 > best.r2) best = alt;
    return best;
  }
  const glm::dvec3 off = (glm::dot(ac, ac) * glm::cross(n, ab) + glm::dot(ab, ab) * glm::cross(ac, n)) / (2.0 * n2);
  return {a + off, glm::dot(off, off)};
}

std::uint64_t next(std::uint64_t& s) {
  s ^= s << 13;
  s ^= s >> 7;
  s ^= s << 17;
  return s;
}

using lanes::pick;
using lanes::splat;
using lanes::V2;

// The widest direction of a front-facing set: max |a x d|^2 / (a.d)^2 (no root or division per
// point); a division only when a new widest one is found.
struct Widest {
  double ratio = -1.0;
  glm::dvec3 at{0.0};
  void take(const glm::dvec3& d, double along, double across2) {
    if (across2 > ratio * along * along) {
      ratio = across2 / (along * along);
      at = d;
    }
  }
};

Cone coneFromAxis(const glm::dvec3& axis, std::span<const glm::dvec3> units) {
  Cone cone;
  cone.axis = axis;
  // atan2(|a x u|, a.u): acos loses half the digits for the narrow cones of far lights. It is
  // taken once, for the widest direction: in front of the axis the angle grows with
  // |a x u|^2 / (a.u)^2 (no root, no atan per direction); anything at or past 90 degrees is
  // measured on its own.
  Widest widest;
  widest.at = axis;
  double worstBehind = 0.0;
  for (const auto& u : units) {
    const glm::dvec3 c = glm::cross(axis, u);
    const double d = glm::dot(axis, u), c2 = glm::dot(c, c);
    if (d > 0.0) widest.take(u, d, c2);
    else worstBehind = std::max(worstBehind, std::atan2(std::sqrt(c2), d));
  }
  const double front = std::atan2(glm::length(glm::cross(axis, widest.at)), glm::dot(axis, widest.at));
  cone.halfAngle = std::max(front, worstBehind);
  cone.valid = cone.halfAngle < std::numbers::pi / 2.0 - 1e-9;
  return cone;
}

// Cold and out of line: the normalising loops stay free of its string work.
[[gnu::cold, gnu::noinline]] glm::dvec3 unitChecked(const glm::dvec3& v, std::size_t i) {
  if (!isFinite(v)) throw std::invalid_argument("direction " + std::to_string(i) + " is not finite");
  const double len = glm::length(v);
  if (!(len > 0.0)) throw std::invalid_argument("direction " + std::to_string(i) + " is the zero vector");
  return v / len;
}

// Welzl with 0..3 boundary points, as loops over p in its order. A 4th boundary point only arises
// when the points are not in an open hemisphere (4 points on the unit sphere span the sphere
// itself); then the ball through 3 points is kept and the hemisphere test afterwards reports it.
Ball welzl(std::span<const glm::dvec3> p) {
  Ball b{p[0], 0.0};
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (contains(b, p[i])) continue;
    b = Ball{p[i], 0.0};
    for (std::size_t j = 0; j < i; ++j) {
      if (contains(b, p[j])) continue;
      b = ball2(p[i], p[j]);
      for (std::size_t k = 0; k < j; ++k) {
        if (contains(b, p[k])) continue;
        b = ball3(p[i], p[j], p[k]);
      }
    }
  }
  return b;
}

// Fisher-Yates over p[from..), with a multiply-shift in place of the modulo (an integer division
// per point).
void shuffleFrom(std::span<glm::dvec3> p, std::size_t from, std::uint64_t& s) {
  for (std::size_t i = p.size() - 1; i > from; --i)
    std::swap(p[i], p[from + std::size_t(((next(s) >> 32) * std::uint64_t(i + 1 - from)) >> 32)]);
}

// d / |d| for a finite non-zero d, the same digits wherever it is taken (the core set compares
// directions for equality).
inline glm::dvec3 unitOf(const glm::dvec3& d) { return d * (1.0 / std::sqrt(glm::dot(d, d))); }

// The first point at the apex or not finite: the cone cannot be aimed (fitLightCamera) or the
// direction is named (smallestEnclosingCone).
bool badDirection(const glm::dvec3& d) {
  const double len2 = glm::dot(d, d);
  return !(len2 > 0.0 && len2 < std::numeric_limits<double>::infinity());
}

// all[i] / |all[i]| (unitChecked names a NaN, infinite or zero one).
inline glm::dvec3 unitAt(std::span<const glm::dvec3> all, std::size_t i) {
  if (badDirection(all[i])) [[unlikely]]  // one test for NaN, infinity and zero before the division
    return unitChecked(all[i], i);
  return unitOf(all[i]);
}

// Normalises every direction and moves the ones most likely to be on the cone's boundary to the
// front of p; returns how many. About a guessed centre a0 (the sum of three samples): the least
// and most u.e1, u.e2 (e1, e2 across a0) and the least u.a0, found in the normalising pass itself.
std::size_t normaliseLeadExtremes(std::span<glm::dvec3> p) {
  const std::size_t n = p.size();
  glm::dvec3 guess(0.0);
  for (const std::size_t i : {std::size_t(0), n / 3, 2 * n / 3}) {
    const double len2 = glm::dot(p[i], p[i]);  // a bad one is named by the pass below
    if (len2 > 0.0 && len2 < std::numeric_limits<double>::infinity()) guess += p[i] * (1.0 / std::sqrt(len2));
  }
  const double len = glm::length(guess);
  const glm::dvec3 a0 = len > 0.0 ? guess / len : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 e1 = anyPerpendicular(a0), e2 = glm::cross(a0, e1);
  // Scalars, not arrays: the loop keeps everything in registers (arrays of keys went through the
  // stack and stalled on store forwarding).
  double b0 = -1e300, b1 = -1e300, b2 = -1e300, b3 = -1e300, b4 = -1e300;
  std::size_t i0 = 0, i1 = 0, i2 = 0, i3 = 0, i4 = 0;
  auto keep = [](double key, std::size_t i, double& best, std::size_t& at) {
    const bool more = key > best;
    best = more ? key : best;
    at = more ? i : at;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 v = p[i];
    const double len2 = glm::dot(v, v);
    double ux, uy, uz;
    if (!(len2 > 0.0 && len2 < std::numeric_limits<double>::infinity())) [[unlikely]] {
      const glm::dvec3 w = unitChecked(p[i], i);
      ux = w.x, uy = w.y, uz = w.z;
    } else {
      const glm::dvec3 w = unitOf(v);
      ux = w.x, uy = w.y, uz = w.z;
    }
    p[i].x = ux, p[i].y = uy, p[i].z = uz;
    const double x = ux * e1.x + uy * e1.y + uz * e1.z, y = ux * e2.x + uy * e2.y + uz * e2.z;
    const double z = ux * a0.x + uy * a0.y + uz * a0.z;
    keep(x, i, b0, i0);
    keep(-x, i, b1, i1);
    keep(y, i, b2, i2);
    keep(-y, i, b3, i3);
    keep(-z, i, b4, i4);
  }
  std::size_t ext[5] = {i0, i1, i2, i3, i4};
  std::size_t head = 0;
  for (int k = 0; k < 5; ++k) {
    bool seen = false;
    for (int m = 0; m < k; ++m) seen = seen || ext[m] == ext[k];
    if (seen) continue;
    std::swap(p[head], p[ext[k]]);
    for (int m = k + 1; m < 5; ++m)  // an index the swap moved
      if (ext[m] == head) ext[m] = ext[k];
    ++head;
  }
  return head;
}

// The smallest ball over many unit vectors without shuffling them all: the ball of a small
// core set (first the extremes) is grown by the points outside it (moved behind the core) until
// it holds every point; the ball of a subset that holds the whole set is the whole set's ball.
// Usually two scans; after kRounds the plain Welzl over every point decides.
Ball coreSetBall(std::span<glm::dvec3> p, std::uint64_t& s) {
  constexpr int kRounds = 16;
  const std::size_t n = p.size();
  const std::size_t head = normaliseLeadExtremes(p);
  std::size_t core = head;
  Ball b = welzl(p.first(core));
  for (int round = 0; round < kRounds; ++round) {
    const std::size_t before = core;
    for (std::size_t i = core; i < n; ++i)
      if (!contains(b, p[i])) std::swap(p[i], p[core++]);
    if (core == before) return b;
    shuffleFrom(p.first(core), head, s);  // Welzl's expected linear time over the core
    b = welzl(p.first(core));
  }
  shuffleFrom(p, head, s);
  return welzl(p);
}

// Every direction (points - apex) normalised into core, then Welzl over all of it: few points,
// or the core set did not settle in kRounds (the points need not fit in a hemisphere).
ConeFit coneOverAll(const glm::dvec3& apex, std::span<const glm::dvec3> points, std::vector<glm::dvec3>& core,
                    std::uint64_t& s) {
  const std::size_t n = points.size();
  core.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    core[i] = points[i] - apex;
    if (badDirection(core[i])) {
      ConeFit f;
      f.bad = i;
      return f;
    }
  }
  Ball b;
  if (n < 16) {
    for (std::size_t i = 0; i < n; ++i) core[i] = unitAt(core, i);
    shuffleFrom(core, 0, s);
    b = welzl(core);
  } else {
    b = coreSetBall(core, s);
  }
  ConeFit f;
  const double cl = glm::length(b.c);
  if (!(cl > 1e-9)) {
    f.cone = coneFromAxis(core[0], core);
    f.cone.valid = false;
  } else {
    // The half-angle is measured, not derived from the radius, so the cone holds every input.
    f.cone = coneFromAxis(b.c / cl, core);
  }
  for (const glm::dvec3& p : points) {
    const double z = glm::dot(p - apex, f.cone.axis);
    f.minAlong = std::min(f.minAlong, z);
    f.maxAlong = std::max(f.maxAlong, z);
  }
  return f;
}

// Every stride-th direction of the points into core (raw, coreSetBall normalises them); false,
// with the index in bad, at the first direction too short or not finite.
bool sampleCore(const glm::dvec3& apex, std::span<const glm::dvec3> points, std::size_t stride,
                std::vector<glm::dvec3>& core, std::size_t& bad) {
  core.clear();
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const glm::dvec3 d = points[i] - apex;
    if (badDirection(d)) {
      bad = i;
      return false;
    }
    core.push_back(d);
  }
  return true;
}

// Keeps only the directions new to the core past `before` (Welzl on pairs of equal points grew
// the cap): both parts sorted, the new part without its repeats and without what the core holds.
void keepNewDirections(std::vector<glm::dvec3>& core, std::size_t before) {
  auto less = [](const glm::dvec3& p, const glm::dvec3& q) {
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  };
  const auto old = core.begin() + std::ptrdiff_t(before);
  std::sort(core.begin(), old, less);
  std::sort(old, core.end(), less);
  auto kept = old;
  for (auto it = old; it != core.end(); ++it)
    if ((kept == old || *(kept - 1) != *it) && !std::binary_search(core.begin(), old, *it, less)) *kept++ = *it;
  core.erase(kept, core.end());
}

// The widest of the core's unit directions around axis a (their tan^2 measured on the core's own
// points, all inside the ball: exact digits); false when one is not in front of the apex.
bool capOfCore(const glm::dvec3& a, std::span<const glm::dvec3> core, Widest& capped) {
  bool front = true;
  for (const glm::dvec3& u : core) {
    const double along = glm::dot(a, u);
    front = front && along > 0.0;
    const glm::dvec3 c = glm::cross(a, u);
    capped.take(u, along, glm::dot(c, c));
  }
  return front;
}

// The cone around axis a through its widest direction, and the points' extent [lo, hi] along a.
ConeFit coneThrough(const glm::dvec3& a, const glm::dvec3& widest, double lo, double hi) {
  ConeFit f;
  f.cone.axis = a;
  f.cone.halfAngle = std::atan2(glm::length(glm::cross(a, widest)), glm::dot(a, widest));
  f.cone.valid = f.cone.halfAngle < std::numbers::pi / 2.0 - 1e-9;
  f.minAlong = lo;
  f.maxAlong = hi;
  return f;
}

ConeFit badAt(std::size_t k) {
  ConeFit f;
  f.bad = k;
  return f;
}

}  // namespace

// Many points: the cone of a sample (every stride-th direction, normalised) is grown by the
// directions outside it until one scan over the points finds none outside. The scan works on the
// raw directions d = p - apex with no root or division: d is inside the cap of axis a and
// tan^2 t when a.d > 0 and |a x d|^2 <= tan^2 t (a.d)^2 (cross products keep their digits for the
// 1e-9 rad cones of far lights, where 1 - cos would not). The scan that finds none outside has
// measured the widest direction and the extent along the axis on the way.
ConeFit enclosingConeFrom(const glm::dvec3& apex, std::span<const glm::dvec3> points, std::vector<glm::dvec3>& core) {
  constexpr std::size_t kSample = 96;
  constexpr int kRounds = 16;
  const std::size_t n = points.size();
  if (n == 0) return ConeFit{};
  std::uint64_t s = 0x9E3779B97F4A7C15ull ^ n;
  if (n < 4 * kSample) return coneOverAll(apex, points, core, s);
  if (std::size_t bad = 0; !sampleCore(apex, points, n / kSample, core, bad)) return badAt(bad);
  Ball b = coreSetBall(core, s);  // normalises the sample
  for (int round = 0; round < kRounds; ++round) {
    const double cl = glm::length(b.c);
    if (!(cl > 1e-9)) break;
    const glm::dvec3 a = b.c / cl;
    Widest capped;
    if (!capOfCore(a, core, capped)) break;  // the core's ball reaches past a hemisphere: Welzl over every direction
    const double limit = capped.ratio * (1.0 + 1e-10) + 1e-30;
    const std::size_t before = core.size();
    Widest widest;
    double lo = std::numeric_limits<double>::max(), hi = -std::numeric_limits<double>::max();
    // One point: false for a bad direction (f.bad), else measured, and added to the core if outside.
    auto scan = [&](std::size_t i) {
      const glm::dvec3 d = points[i] - apex;
      const double along = glm::dot(d, a);
      const glm::dvec3 c = glm::cross(a, d);
      const double across2 = glm::dot(c, c);
      // Every point in front is measured: the scan that finds none outside is the last.
      if (along > 0.0) [[likely]] {
        widest.take(d, along, across2);
        lo = std::min(lo, along);
        hi = std::max(hi, along);
        if (across2 <= limit * along * along) [[likely]]
          return true;
      }
      if (badDirection(d)) [[unlikely]]
        return false;
      // Outside, or a direction already in the core failing only by rounding (the cap's ratio
      // was taken on its unit vector, this one on the raw direction): dropped below.
      core.push_back(unitOf(d));
      return true;
    };
    // Four points at a time in the common case (in front, inside the cap, not the widest so far),
    // two to a vector register: glm's dot and cross written out in their order of operations, so
    // the same digits as scan(); any other four go through scan() one by one, in order. On
    // bench_psm_setup's 1,000 boxes (6,134 points, two scans) this is a sixth of the set-up.
    const V2 ax = splat(a.x), ay = splat(a.y), az = splat(a.z);
    const V2 px = splat(apex.x), py = splat(apex.y), pz = splat(apex.z), zero = splat(0.0);
    auto common = [&](std::size_t j, V2& along) {
      const glm::dvec3 &p = points[j], &q = points[j + 1];
      const V2 dx = V2{p.x, q.x} - px, dy = V2{p.y, q.y} - py, dz = V2{p.z, q.z} - pz;
      along = (dx * ax + dy * ay) + dz * az;
      const V2 cx = ay * dz - dy * az, cy = az * dx - dz * ax, cz = ax * dy - dx * ay;
      const V2 across2 = (cx * cx + cy * cy) + cz * cz;
      return (along > zero) & (across2 <= (splat(limit) * along) * along) &
             (across2 <= (splat(widest.ratio) * along) * along);
    };
    V2 lo2 = splat(lo), hi2 = splat(hi);
    std::size_t i = 0;
    for (; i + 3 < n; i += 4) {
      V2 a0, a1;
      if (lanes::both(common(i, a0) & common(i + 2, a1))) [[likely]] {
        lo2 = pick(a0 < lo2, a0, lo2);
        hi2 = pick(a0 > hi2, a0, hi2);
        lo2 = pick(a1 < lo2, a1, lo2);
        hi2 = pick(a1 > hi2, a1, hi2);
        continue;
      }
      for (std::size_t k = i; k < i + 4; ++k)
        if (!scan(k)) return badAt(k);
    }
    for (; i < n; ++i)
      if (!scan(i)) return badAt(i);
    lo = std::min({lo, lo2[0], lo2[1]});
    hi = std::max({hi, hi2[0], hi2[1]});
    keepNewDirections(core, before);
    if (core.size() == before) return coneThrough(a, widest.at, lo, hi);
    shuffleFrom(core, 0, s);  // Welzl's expected linear time over the core
    b = welzl(core);
  }
  return coneOverAll(apex, points, core, s);
}

Cone smallestEnclosingCone(std::span<const glm::dvec3> directions) {
  thread_local std::vector<glm::dvec3> core;
  const ConeFit f = enclosingConeFrom(glm::dvec3(0.0), directions, core);
  if (f.bad < directions.size()) unitChecked(directions[f.bad], f.bad);  // names it and throws
  return f.cone;
}

Cone smallestEnclosingConeBruteForce(std::span<const glm::dvec3> dirs) {
  const std::size_t n = dirs.size();
  if (n == 0) return Cone{};
  std::vector<glm::dvec3> u(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = unitChecked(dirs[i], i);
  Cone best;
  best.halfAngle = 1e300;
  auto consider = [&](const glm::dvec3& axisRaw) {
    const double len = glm::length(axisRaw);
    if (!(len > 1e-12)) return;
    for (double sign : {1.0, -1.0}) {
      const Cone c = coneFromAxis(sign * axisRaw / len, u);
      if (c.halfAngle < best.halfAngle) best = c;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    consider(u[i]);
    for (std::size_t j = i + 1; j < n; ++j) {
      consider(u[i] + u[j]);
      // Through three: the circle's centre (the circumcentre, in their plane) as the axis; the
      // plane's normal would lose the axis' digits for the 1e-9 rad cones of far lights.
      for (std::size_t k = j + 1; k < n; ++k) consider(ball3(u[i], u[j], u[k]).c);
    }
  }
  return best;
}

}  // namespace shadowlab::psm

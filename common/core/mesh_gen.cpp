#include "core/mesh_gen.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace shadowlab {

// ---- randomness ---------------------------------------------------------------------------------
std::uint64_t SplitMix64::next() {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
// 24 bits fill a float mantissa exactly, so the result is < 1 and platform-independent.
float SplitMix64::uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }
float SplitMix64::uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
int SplitMix64::below(int n) { return n <= 1 ? 0 : int(next() % std::uint64_t(n)); }

std::uint64_t hashCell(std::int64_t x, std::int64_t y, std::uint64_t seed) {
  SplitMix64 mix(seed ^ (std::uint64_t(x) * 0xD6E8FEB86659FD93ull) ^ (std::uint64_t(y) * 0xA0761D6478BD642Full));
  return mix.next();
}

float valueNoise(float x, float y, std::uint64_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const auto ix = std::int64_t(fx), iy = std::int64_t(fy);
  float tx = x - fx, ty = y - fy;
  tx = tx * tx * (3.0f - 2.0f * tx);  // smoothstep: no creases at lattice lines
  ty = ty * ty * (3.0f - 2.0f * ty);
  auto v = [&](std::int64_t dx, std::int64_t dy) {
    return float(hashCell(ix + dx, iy + dy, seed) >> 40) * (1.0f / 16777215.0f);
  };
  const float a = v(0, 0) + (v(1, 0) - v(0, 0)) * tx;
  const float b = v(0, 1) + (v(1, 1) - v(0, 1)) * tx;
  return a + (b - a) * ty;
}

float fbmNoise(float x, float y, int octaves, std::uint64_t seed) {
  float sum = 0.0f, amplitude = 1.0f, norm = 0.0f, frequency = 1.0f;
  for (int o = 0; o < std::max(octaves, 1); ++o) {
    sum += amplitude * valueNoise(x * frequency, y * frequency, seed + std::uint64_t(o) * 0x632BE59BD9B4E019ull);
    norm += amplitude;
    amplitude *= 0.5f;
    frequency *= 2.0f;
  }
  return std::clamp(sum / norm, 0.0f, 1.0f);
}

// ---- helpers ------------------------------------------------------------------------------------
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.1415926535897932384626433832795;

void requireAtLeast(const char* function, const char* what, int value, int minimum) {
  if (value < minimum)
    throw std::invalid_argument(std::string(function) + ": " + what + " must be >= " + std::to_string(minimum) +
                                ", got " + std::to_string(value));
}

// Triangulates a grid of (rows+1) x (cols+1) vertices stored row-major from `base`. The winding
// makes each triangle face along (row direction) x (column direction); callers lay out their
// grids so that this is the outside.
void emitGrid(Mesh& mesh, std::uint32_t base, int rows, int cols) {
  const std::uint32_t stride = std::uint32_t(cols) + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const std::uint32_t a = base + std::uint32_t(j) * stride + std::uint32_t(i);
      const std::uint32_t b = a + 1, c = a + stride, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
}

void reserve(Mesh& mesh, std::size_t vertices, std::size_t triangles) {
  mesh.positions.reserve(vertices);
  mesh.normals.reserve(vertices);
  mesh.uvs.reserve(vertices);
  mesh.indices.reserve(triangles * 3);
}

void push(Mesh& mesh, const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
  mesh.positions.push_back(p);
  mesh.normals.push_back(n);
  mesh.uvs.push_back(uv);
}

// A swept tube (torus, knot): `centre`, `normal` and `binormal` give the frame of each of the
// `segments` rings. Ring `segments` and side `sides` reuse the first ring and side bit for bit,
// so the uv seams weld exactly and the tube is closed.
template <class Frame>
Mesh sweepTube(int segments, int sides, float tube, float uRepeat, Frame frame) {
  Mesh mesh;
  reserve(mesh, std::size_t(segments + 1) * (sides + 1), std::size_t(2) * segments * sides);
  std::vector<glm::vec3> ringPos(std::size_t(segments) * sides), ringNrm(ringPos.size());
  for (int i = 0; i < segments; ++i) {
    glm::dvec3 centre, n, b;
    frame(kTwoPi * i / segments, centre, n, b);
    for (int j = 0; j < sides; ++j) {
      const double theta = kTwoPi * j / sides;
      // Minus: the column direction then crosses the ring direction toward the outside.
      const glm::dvec3 dir = glm::normalize(std::cos(theta) * n - std::sin(theta) * b);
      ringPos[std::size_t(i) * sides + j] = glm::vec3(centre + double(tube) * dir);
      ringNrm[std::size_t(i) * sides + j] = glm::vec3(dir);
    }
  }
  for (int i = 0; i <= segments; ++i)
    for (int j = 0; j <= sides; ++j) {
      const std::size_t k = std::size_t(i % segments) * sides + std::size_t(j % sides);
      push(mesh, ringPos[k], glm::normalize(ringNrm[k]),
           {uRepeat * float(i) / float(segments), float(j) / float(sides)});
    }
  emitGrid(mesh, 0, segments, sides);
  return mesh;
}

}  // namespace

// ---- shapes -------------------------------------------------------------------------------------
Mesh makePlane(float size, int subdivisions, float uvRepeat) {
  requireAtLeast("makePlane", "subdivisions", subdivisions, 1);
  const int n = subdivisions;
  Mesh mesh;
  reserve(mesh, std::size_t(n + 1) * (n + 1), std::size_t(2) * n * n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float s = float(i) / float(n), t = float(j) / float(n);
      // Rows run along +z and columns along +x: z x x = +y, the plane's front.
      push(mesh, {(s - 0.5f) * size, 0.0f, (t - 0.5f) * size}, {0, 1, 0}, {s * uvRepeat, t * uvRepeat});
    }
  emitGrid(mesh, 0, n, n);
  return mesh;
}

Mesh makeBox(const glm::vec3& extents, int subdivisions) {
  requireAtLeast("makeBox", "subdivisions", subdivisions, 1);
  const int n = subdivisions;
  Mesh mesh;
  reserve(mesh, std::size_t(6) * (n + 1) * (n + 1), std::size_t(12) * n * n);
  // Each face as seen from outside: its normal and the direction that is up in its texture.
  const glm::vec3 faces[6][2] = {{{1, 0, 0}, {0, 1, 0}},  {{-1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}},
                                 {{0, 0, -1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, -1}}, {{0, -1, 0}, {0, 0, 1}}};
  for (const auto& face : faces) {
    const glm::vec3 normal = face[0], up = face[1];
    const glm::vec3 right = glm::cross(-normal, up);  // u grows to the viewer's right
    const glm::vec3 down = -up;                       // v grows downward: v = 0 is the top row
    const float width = glm::dot(glm::abs(right), extents), height = glm::dot(glm::abs(down), extents);
    const glm::vec3 centre = 0.5f * glm::dot(glm::abs(normal), extents) * normal;
    const auto base = std::uint32_t(mesh.positions.size());
    // Rows run along `down`, columns along `right`: down x right = normal for every face here.
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const float s = float(i) / float(n), t = float(j) / float(n);
        push(mesh, centre + (s - 0.5f) * width * right + (t - 0.5f) * height * down, normal, {s, t});
      }
    emitGrid(mesh, base, n, n);
  }
  return mesh;
}

Mesh makeSphere(float radius, int slices, int stacks) {
  requireAtLeast("makeSphere", "slices", slices, 3);
  requireAtLeast("makeSphere", "stacks", stacks, 2);
  Mesh mesh;
  reserve(mesh, std::size_t(stacks + 1) * (slices + 1), std::size_t(2) * slices * (stacks - 1));
  for (int j = 0; j <= stacks; ++j) {
    const double theta = kPi * j / stacks;  // from the north pole
    for (int i = 0; i <= slices; ++i) {
      const double phi = kTwoPi * (i % slices) / slices;
      glm::vec3 dir(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                    float(std::sin(theta) * std::cos(phi)));
      float u = float(i) / float(slices);
      // Poles exactly on the axis (sin(pi) is not 0 in floating point); their u is the middle of
      // the slice they cap so the texture does not swirl.
      if (j == 0 || j == stacks) {
        dir = {0.0f, j == 0 ? 1.0f : -1.0f, 0.0f};
        u = std::min((float(i) + 0.5f) / float(slices), 1.0f);
      }
      dir = glm::normalize(dir);
      push(mesh, radius * dir, dir, {u, float(j) / float(stacks)});
    }
  }
  // Rows run south (-y at the front), columns east (+x at phi = 0): their cross is outward.
  const std::uint32_t stride = std::uint32_t(slices) + 1;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = std::uint32_t(j) * stride + std::uint32_t(i);
      const std::uint32_t b = a + 1, c = a + stride, d = c + 1;
      if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, c, b});
      if (j != stacks - 1) mesh.indices.insert(mesh.indices.end(), {j == 0 ? a : b, c, d});
    }
  return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, int segments, int sides) {
  requireAtLeast("makeTorus", "segments", segments, 3);
  requireAtLeast("makeTorus", "sides", sides, 3);
  return sweepTube(segments, sides, minorRadius, 1.0f,
                   [&](double phi, glm::dvec3& centre, glm::dvec3& n, glm::dvec3& b) {
                     const glm::dvec3 radial(std::sin(phi), 0.0, std::cos(phi));
                     const glm::dvec3 along(std::cos(phi), 0.0, -std::sin(phi));
                     centre = double(majorRadius) * radial;
                     n = radial;
                     b = glm::cross(along, n);  // (along, n, b) right-handed
                   });
}

Mesh makeTorusKnot(int p, int q, float radius, float tube, int segments, int sides) {
  requireAtLeast("makeTorusKnot", "p", p, 1);
  requireAtLeast("makeTorusKnot", "q", q, 1);
  requireAtLeast("makeTorusKnot", "segments", segments, 3);
  requireAtLeast("makeTorusKnot", "sides", sides, 3);
  const double scale = double(radius) / 3.0;  // the curve below reaches 3 from its centre
  // Several windings share the tube, so the texture repeats along it.
  return sweepTube(segments, sides, tube, float(std::max(p, q)) * 2.0f,
                   [&](double phi, glm::dvec3& centre, glm::dvec3& n, glm::dvec3& b) {
                     const double r = 2.0 + std::cos(q * phi), dr = -q * std::sin(q * phi);
                     const double cp = std::cos(p * phi), sp = std::sin(p * phi);
                     centre = scale * glm::dvec3(r * cp, r * sp, std::sin(q * phi));
                     const glm::dvec3 tangent =
                         glm::normalize(glm::dvec3(dr * cp - p * r * sp, dr * sp + p * r * cp, q * std::cos(q * phi)));
                     // The tangent always turns around the z axis (p r != 0), so it is never
                     // parallel to the radius vector and this frame never degenerates.
                     b = glm::normalize(glm::cross(tangent, centre));
                     n = glm::cross(b, tangent);
                     b = glm::cross(tangent, n);
                   });
}

Mesh makeCylinder(float radius, float height, int segments, bool capped) {
  requireAtLeast("makeCylinder", "segments", segments, 3);
  Mesh mesh;
  reserve(mesh, std::size_t(capped ? 4 : 2) * (segments + 1), std::size_t(capped ? 4 : 2) * segments);
  const float y0 = -0.5f * height, y1 = 0.5f * height;
  std::vector<glm::vec3> dirs(segments);
  for (int i = 0; i < segments; ++i) {
    const double phi = kTwoPi * i / segments;
    dirs[i] = glm::vec3(float(std::sin(phi)), 0.0f, float(std::cos(phi)));
  }
  // Side: one row per segment with [bottom, top]; rows run east, columns up: outward.
  for (int i = 0; i <= segments; ++i) {
    const glm::vec3 d = dirs[i % segments];
    const float u = float(i) / float(segments);
    push(mesh, {radius * d.x, y0, radius * d.z}, d, {u, 1.0f});
    push(mesh, {radius * d.x, y1, radius * d.z}, d, {u, 0.0f});
  }
  emitGrid(mesh, 0, segments, 1);
  if (!capped) return mesh;
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap == 0 ? y1 : y0;
    const glm::vec3 normal{0.0f, cap == 0 ? 1.0f : -1.0f, 0.0f};
    const auto centre = std::uint32_t(mesh.positions.size());
    push(mesh, {0.0f, y, 0.0f}, normal, {0.5f, 0.5f});
    for (int i = 0; i < segments; ++i)  // same float expressions as the side: rims weld exactly
      push(mesh, {radius * dirs[i].x, y, radius * dirs[i].z}, normal,
           {0.5f + 0.5f * dirs[i].x, 0.5f + 0.5f * dirs[i].z});
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t r0 = centre + 1 + std::uint32_t(i), r1 = centre + 1 + std::uint32_t((i + 1) % segments);
      if (cap == 0) mesh.indices.insert(mesh.indices.end(), {centre, r0, r1});
      else mesh.indices.insert(mesh.indices.end(), {centre, r1, r0});
    }
  }
  return mesh;
}

float terrainHeight(float x, float z, float size, float heightScale, std::uint64_t seed) {
  // Four lattice cells across the terrain at the lowest octave: a few hills, not one bump.
  const float scale = size > 0.0f ? 4.0f / size : 0.0f;
  return heightScale * fbmNoise(x * scale, z * scale, 6, seed);
}

Mesh makeTerrain(float size, int resolution, float heightScale, std::uint64_t seed) {
  requireAtLeast("makeTerrain", "resolution", resolution, 1);
  const int n = resolution;
  const float cell = size / float(n);
  // Heights with a one-sample border, so every normal comes from a central difference.
  const int w = n + 3;
  std::vector<float> h(std::size_t(w) * w);
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i)
      h[std::size_t(j) * w + i] = terrainHeight((float(i - 1) / float(n) - 0.5f) * size,
                                                (float(j - 1) / float(n) - 0.5f) * size, size, heightScale, seed);
  auto at = [&](int i, int j) { return h[std::size_t(j + 1) * w + std::size_t(i + 1)]; };
  Mesh mesh;
  reserve(mesh, std::size_t(n + 1) * (n + 1), std::size_t(2) * n * n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float s = float(i) / float(n), t = float(j) / float(n);
      const float dhdx = (at(i + 1, j) - at(i - 1, j)) / (2.0f * cell);
      const float dhdz = (at(i, j + 1) - at(i, j - 1)) / (2.0f * cell);
      push(mesh, {(s - 0.5f) * size, at(i, j), (t - 0.5f) * size}, glm::normalize(glm::vec3(-dhdx, 1.0f, -dhdz)),
           {s, t});
    }
  emitGrid(mesh, 0, n, n);  // rows +z, columns +x: faces up, as the plane
  return mesh;
}

Mesh makeCard(float width, float height) {
  Mesh mesh;
  reserve(mesh, 4, 2);
  const float hw = 0.5f * width;
  push(mesh, {-hw, 0.0f, 0.0f}, {0, 0, 1}, {0.0f, 1.0f});    // bottom left
  push(mesh, {hw, 0.0f, 0.0f}, {0, 0, 1}, {1.0f, 1.0f});     // bottom right
  push(mesh, {-hw, height, 0.0f}, {0, 0, 1}, {0.0f, 0.0f});  // top left
  push(mesh, {hw, height, 0.0f}, {0, 0, 1}, {1.0f, 0.0f});   // top right
  mesh.indices = {0, 1, 3, 0, 3, 2};
  return mesh;
}

// ---- mesh operations ----------------------------------------------------------------------------
void computeSmoothNormals(Mesh& mesh) {
  // Group by exact position; +0.0f turns -0 into +0 so both land in one group.
  struct Key {
    std::uint32_t bits[3];
    bool operator==(const Key& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.bits[0] * 0x9E3779B1u) ^ std::size_t(k.bits[1] * 0x85EBCA77u) ^
             std::size_t(k.bits[2] * 0xC2B2AE3Du);
    }
  };
  std::unordered_map<Key, std::uint32_t, KeyHash> groupOf;
  groupOf.reserve(mesh.positions.size());
  std::vector<std::uint32_t> group(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0f);
    Key key;
    std::memcpy(key.bits, &p, sizeof key.bits);
    group[i] = groupOf.emplace(key, std::uint32_t(groupOf.size())).first->second;
  }
  std::vector<glm::vec3> sum(groupOf.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (a >= group.size() || b >= group.size() || c >= group.size()) continue;
    // The unnormalised cross product weights each face by its area.
    const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    sum[group[a]] += n;
    sum[group[b]] += n;
    sum[group[c]] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 n = sum[group[i]];
    const float len = glm::length(n);
    // Isolated or degenerate vertices still get a unit normal so shading never sees NaN.
    mesh.normals[i] = len > 1e-30f && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0);
  }
}

void flipInsideOut(Mesh& mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  for (glm::vec3& n : mesh.normals) n = -n;
}

}  // namespace shadowlab

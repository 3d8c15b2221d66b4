#include "algorithms/shadow_volume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include <glm/gtc/matrix_inverse.hpp>

namespace shadowlab::volume {

namespace {

// Positions closer than epsilon become one vertex: a uv seam duplicates positions, and a volume
// built on the duplicates would see a boundary edge along every seam. Grid cells of size epsilon;
// each point is compared with the representatives of the 27 cells around it.
std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& positions, float epsilon, std::vector<glm::vec3>& reps) {
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.x * 73856093ll) ^ std::size_t(k.y * 19349663ll) ^ std::size_t(k.z * 83492791ll);
    }
  };
  const double cell = epsilon > 0.0f ? double(epsilon) : 1e-30;
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> grid;
  grid.reserve(positions.size());
  std::vector<std::uint32_t> ids(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    const Key k{std::int64_t(std::floor(p.x / cell)), std::int64_t(std::floor(p.y / cell)),
                std::int64_t(std::floor(p.z / cell))};
    std::uint32_t found = UINT32_MAX;
    for (int dz = -1; dz <= 1 && found == UINT32_MAX; ++dz)
      for (int dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
        for (int dx = -1; dx <= 1 && found == UINT32_MAX; ++dx) {
          auto it = grid.find(Key{k.x + dx, k.y + dy, k.z + dz});
          if (it == grid.end()) continue;
          for (std::uint32_t r : it->second)
            if (glm::length(reps[r] - p) <= epsilon) {
              found = r;
              break;
            }
        }
    if (found == UINT32_MAX) {
      found = std::uint32_t(reps.size());
      reps.push_back(p);
      grid[k].push_back(found);
    }
    ids[i] = found;
  }
  return ids;
}

struct HalfEdge {
  std::uint64_t key;  // (lo << 32) | hi
  bool forward;       // walked lo -> hi
  std::uint32_t face;
  int corner;  // the edge starts at the face's corner `corner`
};

}  // namespace

std::string EdgeAdjacency::report() const {
  if (closed()) return "closed";
  std::string s = "open:";
  auto part = [&](std::size_t n, const char* what) {
    if (n == 0) return;
    s += (s.back() == ':' ? " " : ", ") + std::to_string(n) + " " + what;
  };
  part(boundaryEdges, "boundary edges");
  part(nonManifoldEdges, "non-manifold edges");
  part(inconsistentEdges, "flipped edges");
  return s;
}

EdgeAdjacency buildAdjacency(const Mesh& mesh, float weldEpsilon) {
  EdgeAdjacency adj;
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      throw std::invalid_argument("buildAdjacency: index " + std::to_string(mesh.indices[i]) + " at " +
                                  std::to_string(i) + " is past the " + std::to_string(mesh.positions.size()) +
                                  " positions");
  const std::vector<std::uint32_t> id = weld(mesh.positions, weldEpsilon, adj.positions);

  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t v0 = id[mesh.indices[t]], v1 = id[mesh.indices[t + 1]], v2 = id[mesh.indices[t + 2]];
    if (v0 == v1 || v1 == v2 || v2 == v0) continue;  // collapsed by welding: no area, no edges
    const glm::vec3 &p0 = adj.positions[v0], &p1 = adj.positions[v1], &p2 = adj.positions[v2];
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    const float len = glm::length(n);
    if (!(len > 0.0f)) continue;  // a sliver with no orientation cannot face toward or away
    adj.triangles.insert(adj.triangles.end(), {v0, v1, v2});
    const glm::vec3 u = n / len;
    adj.planes.push_back(glm::vec4(u, -glm::dot(u, p0)));
  }

  const std::size_t faces = adj.faceCount();
  std::vector<HalfEdge> half;
  half.reserve(faces * 3);
  for (std::uint32_t f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = adj.triangles[3 * f + k], b = adj.triangles[3 * f + (k + 1) % 3];
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      half.push_back({(lo << 32) | hi, a < b, f, k});
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : (x.forward != y.forward ? x.forward : x.face < y.face);
  });

  // neighbour[3 f + k]: the face across edge k of face f and that face's corner the edge starts at.
  std::vector<std::int64_t> across(faces * 3, -1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].key == half[i].key) ++j;
    std::vector<const HalfEdge*> fwd, bwd;
    for (std::size_t k = i; k < j; ++k) (half[k].forward ? fwd : bwd).push_back(&half[k]);
    const std::size_t uses = j - i;
    if (uses > 2) ++adj.nonManifoldEdges;
    else if (uses == 2 && bwd.size() != 1) ++adj.inconsistentEdges;
    // Pair opposite walks; whatever is left over is an edge of one face only.
    const std::size_t pairs = std::min(fwd.size(), bwd.size());
    for (std::size_t p = 0; p < pairs; ++p) {
      const HalfEdge &x = *fwd[p], &y = *bwd[p];
      adj.edges.push_back({adj.triangles[3 * x.face + x.corner], adj.triangles[3 * x.face + (x.corner + 1) % 3],
                           std::int32_t(x.face), std::int32_t(y.face)});
      across[3 * x.face + x.corner] = std::int64_t(3 * y.face + y.corner);
      across[3 * y.face + y.corner] = std::int64_t(3 * x.face + x.corner);
    }
    for (auto* list : {&fwd, &bwd})
      for (std::size_t p = pairs; p < list->size(); ++p) {
        const HalfEdge& x = *(*list)[p];
        adj.edges.push_back({adj.triangles[3 * x.face + x.corner], adj.triangles[3 * x.face + (x.corner + 1) % 3],
                             std::int32_t(x.face), -1});
        if (uses == 1) ++adj.boundaryEdges;
      }
    i = j;
  }

  adj.adjacencyIndices.resize(faces * 6);
  for (std::size_t f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t o = across[3 * f + k];
      // The neighbour's vertex opposite the shared edge: the corner after the edge's end in its walk.
      const std::uint32_t opposite =
          o >= 0 ? adj.triangles[3 * (o / 3) + (o % 3 + 2) % 3] : adj.triangles[3 * f + (k + 2) % 3];
      adj.adjacencyIndices[6 * f + 2 * k] = adj.triangles[3 * f + k];
      adj.adjacencyIndices[6 * f + 2 * k + 1] = opposite;
    }
  return adj;
}

glm::vec4 homogeneousLight(const Light& light) {
  return light.kind == LightKind::Directional ? glm::vec4(-glm::normalize(light.direction), 0.0f)
                                              : glm::vec4(light.position, 1.0f);
}

std::vector<SilhouetteEdge> findSilhouette(const EdgeAdjacency& adj, const glm::vec4& light, SilhouetteTest test,
                                           bool twoSided) {
  // The corner of face f that is not on edge (a, b).
  auto third = [&](std::int32_t f, std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = adj.triangles[3 * std::size_t(f) + k];
      if (v != a && v != b) return adj.positions[v];
    }
    return adj.positions[a];
  };
  std::vector<SilhouetteEdge> out;
  for (const Edge& e : adj.edges) {
    const bool lit0 = facesLight(adj.planes[std::size_t(e.face0)], light);
    if (e.face1 < 0) {
      if (lit0) out.push_back({e.a, e.b});
      else if (twoSided) out.push_back({e.b, e.a});  // the face flipped toward the light walks b -> a
      continue;
    }
    const std::size_t before = out.size();
    if (test) {
      if (test(adj.positions[e.a], adj.positions[e.b], third(e.face0, e.a, e.b), third(e.face1, e.a, e.b), light))
        out.push_back(lit0 ? SilhouetteEdge{e.a, e.b} : SilhouetteEdge{e.b, e.a});
    } else {
      const bool lit1 = facesLight(adj.planes[std::size_t(e.face1)], light);
      if (lit0 && !lit1) out.push_back({e.a, e.b});
      else if (lit1 && !lit0) out.push_back({e.b, e.a});  // face1 walks b -> a
    }
    if (twoSided && out.size() > before) out.push_back(out.back());  // the flipped faces' volume's side
  }
  return out;
}

bool isSilhouette(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                  const glm::vec4& light) {
  auto faces = [&](const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    return facesLight(glm::vec4(n, -glm::dot(n, p0)), light);
  };
  return faces(a, b, c) != faces(b, a, d);
}

VolumeCounts buildVolume(const EdgeAdjacency& adj, const glm::vec4& light, bool caps, std::vector<glm::vec4>& out,
                         std::vector<SilhouetteEdge>* silhouette, SilhouetteTest test, bool twoSided) {
  VolumeCounts n;
  const std::vector<SilhouetteEdge> edges = findSilhouette(adj, light, test, twoSided);
  n.silhouetteEdges = edges.size();
  for (const SilhouetteEdge& e : edges) {
    const glm::vec3 &a = adj.positions[e.a], &b = adj.positions[e.b];
    out.insert(out.end(),
               {glm::vec4(b, 1), glm::vec4(a, 1), glm::vec4(a, 0), glm::vec4(b, 1), glm::vec4(a, 0), glm::vec4(b, 0)});
    n.sideTriangles += 2;
  }
  if (caps)
    for (std::size_t f = 0; f < adj.faceCount(); ++f) {
      if (facesLight(adj.planes[f], light)) continue;
      const glm::vec3 &p0 = adj.positions[adj.triangles[3 * f]], &p1 = adj.positions[adj.triangles[3 * f + 1]],
                      &p2 = adj.positions[adj.triangles[3 * f + 2]];
      out.insert(out.end(), {glm::vec4(p0, 1), glm::vec4(p2, 1), glm::vec4(p1, 1),    // near cap, reversed
                             glm::vec4(p0, 0), glm::vec4(p1, 0), glm::vec4(p2, 0)});  // far cap at infinity
      n.capTriangles += 2;
    }
  if (silhouette) *silhouette = edges;
  return n;
}

glm::mat4 infinitePerspective(float fovY, float aspect, float nearZ, float epsilon) {
  if (!(fovY > 0.0f && fovY < 3.14159f) || !(aspect > 0.0f) || !(nearZ > 0.0f))
    throw std::invalid_argument("infinitePerspective: needs 0 < fovY < pi, aspect > 0, nearZ > 0");
  const float f = 1.0f / std::tan(0.5f * fovY);
  glm::mat4 m(0.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = epsilon - 1.0f;
  m[2][3] = -1.0f;
  m[3][2] = nearZ * (epsilon - 2.0f);
  return m;
}

glm::mat4 makeFarInfinite(const glm::mat4& p, float epsilon) {
  // glm::perspective: m[2][2] = -(f + n) / (f - n), m[3][2] = -2 f n / (f - n), m[2][3] = -1, so
  // m[3][2] / (m[2][2] - 1) = n.
  if (p[2][3] != -1.0f || p[3][3] != 0.0f || !(p[2][2] < -1.0f))
    throw std::invalid_argument("makeFarInfinite: not a finite OpenGL perspective matrix");
  const float n = p[3][2] / (p[2][2] - 1.0f);
  glm::mat4 m = p;
  m[2][2] = epsilon - 1.0f;
  m[3][2] = n * (epsilon - 2.0f);
  return m;
}

NearRect nearRect(const glm::mat4& view, float fovY, float aspect, float nearZ) {
  const glm::mat4 toWorld = glm::inverse(view);
  const float h = nearZ * std::tan(0.5f * fovY), w = h * aspect;
  NearRect r;
  const glm::vec2 c[4] = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
  for (int i = 0; i < 4; ++i) r.corners[i] = glm::vec3(toWorld * glm::vec4(c[i], -nearZ, 1.0f));
  return r;
}

bool volumeMayReachNearPlane(const Aabb& bounds, const NearRect& near, const glm::vec4& light) {
  if (bounds.empty()) return false;
  const glm::vec3* c = near.corners;
  const glm::vec3 centre = 0.25f * (c[0] + c[1] + c[2] + c[3]);
  const glm::vec3 normal = glm::cross(c[1] - c[0], c[2] - c[0]);
  const float size = glm::length(c[2] - c[0]);
  const glm::vec3 L(light);
  // A point inside the hull of the rectangle and the light: halfway to a point light, or one
  // rectangle size toward a directional one.
  const glm::vec3 inside = light.w != 0.0f ? 0.5f * (centre + L / light.w) : centre + size * glm::normalize(L);
  const float lightSide = light.w != 0.0f ? glm::dot(normal, L / light.w - centre) : glm::dot(normal, L);
  // The light (or its direction) in the near plane: the hull is flat; be safe and say yes.
  if (std::abs(lightSide) <= 1e-6f * glm::length(normal) *
                                 (light.w != 0.0f ? std::max(size, glm::length(L / light.w - centre)) : glm::length(L)))
    return true;

  std::array<std::pair<glm::vec3, glm::vec3>, 5> planes;  // (point, inward normal)
  planes[0] = {centre, lightSide > 0 ? normal : -normal};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 &a = c[i], &b = c[(i + 1) % 4];
    const glm::vec3 toLight = light.w != 0.0f ? L / light.w - a : L;
    glm::vec3 n = glm::cross(b - a, toLight);
    if (glm::dot(n, inside - a) < 0) n = -n;
    planes[std::size_t(i + 1)] = {a, n};
  }
  for (const auto& [p, n] : planes) {
    bool allOutside = true;
    for (int k = 0; k < 8 && allOutside; ++k) {
      const glm::vec3 corner((k & 1) ? bounds.max.x : bounds.min.x, (k & 2) ? bounds.max.y : bounds.min.y,
                             (k & 4) ? bounds.max.z : bounds.min.z);
      allOutside = glm::dot(n, corner - p) < 0.0f;
    }
    if (allOutside) return false;
  }
  return true;
}

StencilOps stencilOps(bool zFail) {
  using enum StencilOp;
  if (zFail) return {{Keep, DecrWrap, Keep}, {Keep, IncrWrap, Keep}};
  return {{Keep, Keep, IncrWrap}, {Keep, Keep, DecrWrap}};
}

float lightReach(const Light& light, float threshold) {
  if (light.kind == LightKind::Directional) return 1e30f;
  const float peak = light.intensity * std::max({light.color.x, light.color.y, light.color.z});
  const float k = peak / threshold;  // the denominator at which the light fades to the threshold
  const glm::vec3 c = light.attenuation;
  if (c.x >= k) return 0.0f;
  if (c.z > 0.0f) return (-c.y + std::sqrt(c.y * c.y - 4.0f * c.z * (c.x - k))) / (2.0f * c.z);
  if (c.y > 0.0f) return (k - c.x) / c.y;
  return 1e30f;
}

ScissorRect scissorForSphere(const glm::vec3& centre, float radius, const glm::mat4& viewProj, int width, int height) {
  const ScissorRect full{0, 0, width, height};
  if (!(radius < 1e29f)) return full;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner = centre + radius * glm::vec3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
    const glm::vec4 clip = viewProj * glm::vec4(corner, 1.0f);
    if (clip.w <= 1e-6f) return full;  // behind the eye: the projection of the box is unbounded
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  if (hi.x < -1 || hi.y < -1 || lo.x > 1 || lo.y > 1) return {};
  lo = glm::clamp(lo, glm::vec2(-1), glm::vec2(1));
  hi = glm::clamp(hi, glm::vec2(-1), glm::vec2(1));
  const int x0 = int(std::floor((lo.x * 0.5f + 0.5f) * float(width))),
            x1 = int(std::ceil((hi.x * 0.5f + 0.5f) * float(width)));
  const int y0 = int(std::floor((lo.y * 0.5f + 0.5f) * float(height))),
            y1 = int(std::ceil((hi.y * 0.5f + 0.5f) * float(height)));
  return {x0, y0, x1 - x0, y1 - y0};
}

void buildSceneVolumes(const Scene& scene, const std::vector<EdgeAdjacency>& adjacency, const glm::vec4& lightWorld,
                       const std::function<bool(std::size_t)>& casts, SilhouetteTest test, SceneVolumes& out) {
  out.triangles.clear(), out.first.clear(), out.sides.clear(), out.caps.clear(), out.silhouette.clear();
  std::vector<glm::vec4> local;
  std::vector<SilhouetteEdge> edges;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    out.first.push_back(int(out.triangles.size()));
    out.sides.push_back(0);
    out.caps.push_back(0);
    if (!casts(o)) continue;
    const SceneObject& obj = scene.objects[o];
    const EdgeAdjacency& adj = adjacency[obj.mesh];
    local.clear();
    // In the object's space: the model matrix goes on afterwards, vertex by vertex.
    const VolumeCounts n =
        buildVolume(adj, glm::inverse(obj.model) * lightWorld, adj.closed(), local, &edges, test, !adj.closed());
    out.sides.back() = int(n.sideTriangles * 3);
    out.caps.back() = int(local.size()) - out.sides.back();
    for (const glm::vec4& v : local)
      out.triangles.push_back(glm::vec4(glm::vec3(obj.model * glm::vec4(glm::vec3(v), 1)), v.w));
    for (const auto& e : edges) {
      out.silhouette.push_back(glm::vec3(obj.model * glm::vec4(adj.positions[e.a], 1)));
      out.silhouette.push_back(glm::vec3(obj.model * glm::vec4(adj.positions[e.b], 1)));
    }
  }
}

}  // namespace shadowlab::volume

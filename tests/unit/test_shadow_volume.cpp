// Shadow volumes (algorithms/shadow_volume): adjacency and closedness, silhouettes, the volume's
// closedness and orientation, the infinite projection, the near-plane test, the stencil tables,
// the light's reach and its scissor rectangle. Expected values are worked out in the comments.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh_gen.hpp"
#include "algorithms/shadow_volume.hpp"

using namespace shadowlab;
using namespace shadowlab::volume;

namespace {

// The volume made finite (points at infinity pushed 1000 units away from the light) as a Mesh, so
// the topology analysis and the divergence theorem can check it.
Mesh finiteVolume(const std::vector<glm::vec4>& tris, const glm::vec4& light) {
  Mesh m;
  for (const glm::vec4& v : tris) {
    glm::vec3 p(v);
    if (v.w == 0.0f)
      p += 1000.0f * glm::normalize(light.w != 0.0f ? p - glm::vec3(light) / light.w : -glm::vec3(light));
    m.indices.push_back(std::uint32_t(m.positions.size()));
    m.positions.push_back(p);
  }
  return m;
}
double signedVolume(const Mesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    v += glm::dot(glm::dvec3(m.positions[m.indices[t]]),
                  glm::cross(glm::dvec3(m.positions[m.indices[t + 1]]), glm::dvec3(m.positions[m.indices[t + 2]]))) /
         6.0;
  return v;
}

}  // namespace

TEST_CASE("volume.adjacency: a box is closed: 8 welded corners, 12 faces, 18 edges, every edge paired") {
  // makeBox gives each face its own 4 vertices (24); welding leaves the 8 corners. Euler:
  // V - E + F = 2 with F = 12 triangles -> E = 18.
  const EdgeAdjacency adj = buildAdjacency(makeBox(glm::vec3(1)));
  CHECK(adj.positions.size() == 8);
  CHECK(adj.faceCount() == 12);
  CHECK(adj.edges.size() == 18);
  CHECK(adj.closed());
  CHECK(adj.report() == "closed");
  for (const Edge& e : adj.edges) CHECK(e.face1 >= 0);
  REQUIRE(adj.adjacencyIndices.size() == 72);
  // Each face's adjacency vertex across an edge is a corner of the box that is not on that edge.
  for (std::size_t f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = adj.adjacencyIndices[6 * f + 2 * k], b = adj.adjacencyIndices[6 * f + (2 * k + 2) % 6];
      const std::uint32_t o = adj.adjacencyIndices[6 * f + 2 * k + 1];
      CHECK(o != a);
      CHECK(o != b);
    }
}

TEST_CASE("volume.adjacency: a sphere with its uv seam and poles welded is closed") {
  const EdgeAdjacency adj = buildAdjacency(makeSphere(1.0f, 12, 6));
  // 12 slices, 6 stacks: 12 * 5 ring vertices + 2 poles = 62; faces 2 * 12 * 5 = 120; E = 62 + 120 - 2 = 180.
  CHECK(adj.positions.size() == 62);
  CHECK(adj.faceCount() == 120);
  CHECK(adj.edges.size() == 180);
  CHECK(adj.closed());
}

TEST_CASE("volume.adjacency: open, flipped and bad meshes are reported") {
  SUBCASE("a plane of two triangles: 5 edges, the 4 outer ones open") {
    const EdgeAdjacency adj = buildAdjacency(makePlane(2.0f));
    CHECK(adj.edges.size() == 5);
    CHECK(adj.boundaryEdges == 4);
    CHECK_FALSE(adj.closed());
    CHECK(adj.report() == "open: 4 boundary edges");
  }
  SUBCASE("a box with one triangle turned over: its 3 edges are walked the same way twice") {
    Mesh box = makeBox(glm::vec3(1));
    std::swap(box.indices[1], box.indices[2]);
    const EdgeAdjacency adj = buildAdjacency(box);
    CHECK(adj.inconsistentEdges == 3);
    CHECK(adj.boundaryEdges == 0);
    CHECK(adj.report() == "open: 3 flipped edges");
  }
  SUBCASE("an index past the positions is named") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 7};
    CHECK_THROWS_WITH_AS(buildAdjacency(m), doctest::Contains("index 7"), std::invalid_argument);
  }
}

TEST_CASE("volume.silhouette: a unit box under lights from above and from a corner") {
  const EdgeAdjacency adj = buildAdjacency(makeBox(glm::vec3(1)));
  SUBCASE(
      "sun straight down: only the top faces toward it (sides are edge-on, dot = 0, not toward); the top square's 4 "
      "edges") {
    const auto s = findSilhouette(adj, glm::vec4(0, 1, 0, 0));
    CHECK(s.size() == 4);
    for (const auto& e : s) {
      CHECK(adj.positions[e.a].y == doctest::Approx(0.5f));
      CHECK(adj.positions[e.b].y == doctest::Approx(0.5f));
    }
  }
  SUBCASE("point light at (10, 10, 0): the top and +x faces are lit; the hexagon of 6 edges around them") {
    // Top (y = 0.5) edges to -x, +z, -z sides, and +x (x = 0.5) edges to bottom, +z, -z sides.
    const auto s = findSilhouette(adj, glm::vec4(10, 10, 0, 1));
    CHECK(s.size() == 6);
    for (const auto& e : s) {
      const glm::vec3 a = adj.positions[e.a], b = adj.positions[e.b];
      CHECK((a - b).x * (a - b).y == 0.0f);  // no edge of the shared top/+x ridge diagonal
      CHECK_FALSE((a.x == 0.5f && b.x == 0.5f && a.y == 0.5f && b.y == 0.5f));  // the top/+x ridge is not one
    }
  }
  SUBCASE("light inside the box: every face is turned away, no silhouette") {
    CHECK(findSilhouette(adj, glm::vec4(0, 0, 0, 1)).empty());
  }
  SUBCASE("each silhouette edge runs the way its lit face walks it") {
    const glm::vec4 L(3, 5, 2, 1);
    for (const auto& e : findSilhouette(adj, L)) {
      bool found = false;
      for (std::size_t f = 0; f < adj.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
          if (adj.triangles[3 * f + k] == e.a && adj.triangles[3 * f + (k + 1) % 3] == e.b)
            found = facesLight(adj.planes[f], L);
      CHECK(found);
    }
  }
}

TEST_CASE("volume.silhouette: the four-point form agrees with the adjacency form") {
  // The top-front edge of a box: edge (0,0,0)-(1,0,0); face (a, b, c) with c = (0,0,-1):
  // (1,0,0) x (0,0,-1) = (0,1,0), the top; face (b, a, d) with d = (0,-1,0): (-1,0,0) x (-1,-1,0) =
  // (0,0,1), the front.
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 0, -1), d(0, -1, 0);
  CHECK(isSilhouette(a, b, c, d, glm::vec4(0, 5, -5, 1)));         // above and behind: sees the top only
  CHECK_FALSE(isSilhouette(a, b, c, d, glm::vec4(0, 5, 5, 1)));    // above and in front: sees both
  CHECK_FALSE(isSilhouette(a, b, c, d, glm::vec4(0, -5, -5, 1)));  // below and behind: sees neither
  CHECK(isSilhouette(a, b, c, d, glm::vec4(0, 0, 1, 0)));  // sun from +z: the front only (the top is edge-on: 0)
}

TEST_CASE("volume.build: the volume is closed, faces outward, and counts sides and caps") {
  const EdgeAdjacency adj = buildAdjacency(makeBox(glm::vec3(1)));
  for (const glm::vec4 L : {glm::vec4(0, 10, 0, 1), glm::vec4(10, 10, 3, 1), glm::vec4(-0.3f, 1, 0.2f, 0)}) {
    CAPTURE(L);
    std::vector<glm::vec4> tris;
    std::vector<SilhouetteEdge> sil;
    const VolumeCounts n = buildVolume(adj, L, true, tris, &sil);
    CHECK(n.silhouetteEdges == sil.size());
    CHECK(n.sideTriangles == 2 * n.silhouetteEdges);
    CHECK(tris.size() == 3 * (n.sideTriangles + n.capTriangles));
    const Mesh m = finiteVolume(tris, L);
    const Topology topo = analyseTopology(m, 1e-3f);
    CHECK(topo.closed());
    CHECK(signedVolume(m) > 0.0);  // outward-facing triangles enclose a positive volume
  }
  SUBCASE("sun from above: 4 silhouette edges, 8 sides; 10 faces away from it, each in two caps") {
    std::vector<glm::vec4> tris;
    const VolumeCounts n = buildVolume(adj, glm::vec4(0, 1, 0, 0), true, tris);
    CHECK(n.silhouetteEdges == 4);
    CHECK(n.capTriangles == 20);
    tris.clear();
    CHECK(buildVolume(adj, glm::vec4(0, 1, 0, 0), false, tris).capTriangles == 0);
    CHECK(tris.size() == 24);
  }
}

TEST_CASE("volume.projection: the infinite perspective keeps the near plane and puts infinity just inside") {
  const float fov = 1.0f, aspect = 16.0f / 9.0f, n = 0.1f;
  const glm::mat4 P = infinitePerspective(fov, aspect, n, 0.0f);
  // The near plane still maps to -1: z = -n -> z_clip = n (0 - 2) * ... : (-1)(-n) + n(-2) = -n, w = n.
  const glm::vec4 nearPoint = P * glm::vec4(0, 0, -n, 1);
  CHECK(nearPoint.z / nearPoint.w == doctest::Approx(-1.0f));
  // x and y exactly as glm::perspective.
  const glm::mat4 G = glm::perspective(fov, aspect, n, 100.0f);
  CHECK(P[0][0] == doctest::Approx(G[0][0]));
  CHECK(P[1][1] == doctest::Approx(G[1][1]));
  // A direction (w = 0) straight ahead: z_clip = (eps - 1)(-1) = 1 - eps, w_clip = 1.
  const float eps = 4.8e-7f;
  const glm::vec4 inf = infinitePerspective(fov, aspect, n, eps) * glm::vec4(0, 0, -1, 0);
  CHECK(inf.w == doctest::Approx(1.0f));
  CHECK(inf.z < inf.w);
  CHECK(inf.z == doctest::Approx(1.0f - eps).epsilon(1e-9));
  // A point 1000 units away: depth between the finite one and 1.
  const glm::vec4 far = P * glm::vec4(0, 0, -1000, 1);
  CHECK(far.z / far.w == doctest::Approx(1.0f - 2.0f * n / 1000.0f));
  // Making glm's finite matrix infinite gives the same matrix.
  const glm::mat4 Q = makeFarInfinite(G, eps), R = infinitePerspective(fov, aspect, n, eps);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) CHECK(Q[c][r] == doctest::Approx(R[c][r]).epsilon(1e-5));
  CHECK_THROWS_AS(makeFarInfinite(glm::ortho(-1.f, 1.f, -1.f, 1.f, 0.1f, 10.f)), std::invalid_argument);
  CHECK_THROWS_AS(infinitePerspective(0.0f, 1.0f, 0.1f), std::invalid_argument);
}

TEST_CASE("volume.near: which casters can throw a volume onto the near plane") {
  // Camera at the origin looking down -z, 90 degrees, square, near 1: the rectangle is (+-1, +-1, -1).
  const NearRect r = nearRect(glm::mat4(1.0f), glm::radians(90.0f), 1.0f, 1.0f);
  for (const glm::vec3& c : r.corners) {
    CHECK(std::abs(c.x) == doctest::Approx(1.0f));
    CHECK(std::abs(c.y) == doctest::Approx(1.0f));
    CHECK(c.z == doctest::Approx(-1.0f));
  }
  auto box = [](glm::vec3 c, float h) {
    Aabb b;
    b.extend(c - glm::vec3(h));
    b.extend(c + glm::vec3(h));
    return b;
  };
  SUBCASE("point light ahead at z = -10: the pyramid from the rectangle to it") {
    const glm::vec4 L(0, 0, -10, 1);
    CHECK(volumeMayReachNearPlane(box({0, 0, -5}, 0.5f), r, L));  // on the axis: in its shadow
    // At z = -5 the pyramid's half-width is 1 * (10 - 5) / 9 = 0.56; a box at x 4.5..5.5 is clear of it.
    CHECK_FALSE(volumeMayReachNearPlane(box({5, 0, -5}, 0.5f), r, L));
    // Beyond the light (z = -20): its shadow falls away from the camera.
    CHECK_FALSE(volumeMayReachNearPlane(box({0, 0, -20}, 0.5f), r, L));
    // The camera inside a caster: the rectangle itself is inside the box.
    CHECK(volumeMayReachNearPlane(box({0, 0, 0}, 3.0f), r, L));
  }
  SUBCASE("sun behind the camera (toward +z): the prism from the rectangle back toward it") {
    const glm::vec4 L(0, 0, 1, 0);
    CHECK(volumeMayReachNearPlane(box({0, 0, 3}, 0.5f), r, L));         // behind the viewer: shadows the near plane
    CHECK_FALSE(volumeMayReachNearPlane(box({0, 0, -5}, 0.5f), r, L));  // ahead: its shadow runs away
    CHECK_FALSE(volumeMayReachNearPlane(box({4, 0, 3}, 0.5f), r, L));   // behind but off to the side
  }
  SUBCASE("a light in the near plane: no pyramid to test against, so always z-fail") {
    CHECK(volumeMayReachNearPlane(box({50, 50, -50}, 0.5f), r, glm::vec4(5, 0, -1, 1)));
  }
}

TEST_CASE("volume.stencil: the z-pass and z-fail tables") {
  using enum StencilOp;
  const StencilOps pass = stencilOps(false), fail = stencilOps(true);
  CHECK(pass.front == FaceStencilOps{Keep, Keep, IncrWrap});
  CHECK(pass.back == FaceStencilOps{Keep, Keep, DecrWrap});
  CHECK(fail.front == FaceStencilOps{Keep, DecrWrap, Keep});
  CHECK(fail.back == FaceStencilOps{Keep, IncrWrap, Keep});
}

TEST_CASE("volume.scissor: a light's reach and its rectangle on screen") {
  Light l{LightKind::Point, {0, 0, 0}};
  l.intensity = 1;
  l.color = glm::vec3(1);
  l.attenuation = {1, 0, 1};  // 1 + d^2 = 256 -> d = sqrt(255)
  CHECK(lightReach(l) == doctest::Approx(std::sqrt(255.0f)));
  l.attenuation = {1, 1, 0};  // 1 + d = 256
  CHECK(lightReach(l) == doctest::Approx(255.0f));
  l.attenuation = {300, 0, 1};  // never as bright as 1/256
  CHECK(lightReach(l) == 0.0f);
  l.kind = LightKind::Directional;
  CHECK(lightReach(l) >= 1e29f);

  // viewProj = identity: the sphere's box is its own NDC rectangle: [-0.5, 0.5] -> pixels 25..75 of 100.
  CHECK(scissorForSphere({0, 0, 0}, 0.5f, glm::mat4(1), 100, 100) == ScissorRect{25, 25, 50, 50});
  CHECK(scissorForSphere({5, 0, 0}, 0.5f, glm::mat4(1), 100, 100).width == 0);  // off screen
  CHECK(scissorForSphere({0.9f, 0, 0}, 0.5f, glm::mat4(1), 100, 100) ==
        ScissorRect{70, 25, 30, 50});  // clamped at the edge
  // A perspective camera at the origin: a light sphere around the eye covers the whole screen.
  const glm::mat4 P = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  CHECK(scissorForSphere({0, 0, 0}, 2.0f, P, 64, 48) == ScissorRect{0, 0, 64, 48});
}

TEST_CASE("volume.silhouette: a custom test replaces the plane test on paired edges") {
  const EdgeAdjacency adj = buildAdjacency(makeBox(glm::vec3(1)));
  const glm::vec4 L(10, 10, 3, 1);
  CHECK(findSilhouette(adj, L, &isSilhouette).size() == findSilhouette(adj, L).size());
  // A test that says yes to everything: all 18 edges, each oriented by its lit face where one is lit.
  const SilhouetteTest always = [](const glm::vec3&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                                   const glm::vec4&) { return true; };
  CHECK(findSilhouette(adj, L, always).size() == 18);
}

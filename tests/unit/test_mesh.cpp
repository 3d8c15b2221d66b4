// Meshes: generator counts from their formulas, unit normals, windings that agree with the
// normals, closedness where claimed, and the topology analysis itself on hand-made cases.
#include <doctest/doctest.h>

#include <initializer_list>

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh.hpp"
#include "core/mesh_gen.hpp"

using namespace shadowlab;

namespace {

// Invariants every generated mesh must keep; returns nothing, CHECKs inside so failures point
// at the mesh by the caller's SUBCASE/INFO.
void checkWellFormed(const Mesh& m) {
  REQUIRE(m.normals.size() == m.positions.size());
  REQUIRE(m.uvs.size() == m.positions.size());
  REQUIRE(m.indices.size() % 3 == 0);
  std::size_t badIndex = 0, badNormal = 0, badWinding = 0, nonFinite = 0;
  for (std::uint32_t i : m.indices) badIndex += i >= m.positions.size();
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    badNormal += std::abs(glm::length(m.normals[i]) - 1.0f) > 1e-4f;
    nonFinite += !(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) &&
                   std::isfinite(m.positions[i].z) && std::isfinite(m.uvs[i].x) && std::isfinite(m.uvs[i].y));
  }
  REQUIRE(badIndex == 0);
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const glm::vec3 face = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    const glm::vec3 vertexSide = m.normals[a] + m.normals[b] + m.normals[c];
    // Counter-clockwise front faces: the geometric normal points where the vertex normals do.
    badWinding += glm::dot(face, vertexSide) <= 0.0f;
  }
  CHECK(badNormal == 0);
  CHECK(nonFinite == 0);
  CHECK(badWinding == 0);
}

void checkUvRange(const Mesh& m, float lo, float hi) {
  std::size_t outside = 0;
  for (const glm::vec2& uv : m.uvs) outside += uv.x < lo || uv.x > hi || uv.y < lo || uv.y > hi;
  CHECK(outside == 0);
}

// Every face's normal points away from `centre` (convex shapes).
void checkOutward(const Mesh& m, const glm::vec3& centre) {
  std::size_t inward = 0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    inward += glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) <= 0.0f;
  }
  CHECK(inward == 0);
}

bool sameMesh(const Mesh& a, const Mesh& b) {
  return a.positions == b.positions && a.normals == b.normals && a.uvs == b.uvs && a.indices == b.indices;
}

}  // namespace

TEST_CASE("mesh_gen: plane counts, orientation, uv repeat and its open border") {
  for (int n : {1, 3, 10}) {
    INFO("subdivisions " << n);
    const Mesh m = makePlane(6.0f, n, 4.0f);
    CHECK(m.vertexCount() == std::size_t((n + 1) * (n + 1)));
    CHECK(m.triangleCount() == std::size_t(2 * n * n));
    checkWellFormed(m);
    checkUvRange(m, 0.0f, 4.0f);
    for (const glm::vec3& nrm : m.normals) CHECK(nrm == glm::vec3(0, 1, 0));
    const Aabb box = m.bounds();
    CHECK(box.min == glm::vec3(-3.0f, 0.0f, -3.0f));
    CHECK(box.max == glm::vec3(3.0f, 0.0f, 3.0f));
    const Topology topo = analyseTopology(m);
    // n(n+1) edges along x, as many along z, one diagonal per cell; the border has 4n.
    CHECK(topo.edges == std::size_t(2 * n * (n + 1) + n * n));
    CHECK(topo.boundaryEdges == std::size_t(4 * n));
    CHECK(topo.inconsistentEdges == 0);
    CHECK_FALSE(topo.closed());
  }
}

TEST_CASE("mesh_gen: box counts, bounds, outward faces and closed after welding") {
  for (int n : {1, 4}) {
    INFO("subdivisions " << n);
    const Mesh m = makeBox({2.0f, 4.0f, 6.0f}, n);
    CHECK(m.vertexCount() == std::size_t(6 * (n + 1) * (n + 1)));
    CHECK(m.triangleCount() == std::size_t(12 * n * n));
    checkWellFormed(m);
    checkUvRange(m, 0.0f, 1.0f);
    checkOutward(m, glm::vec3(0.0f));
    CHECK(m.bounds().min == glm::vec3(-1.0f, -2.0f, -3.0f));
    CHECK(m.bounds().max == glm::vec3(1.0f, 2.0f, 3.0f));
    const Topology topo = analyseTopology(m);
    CHECK(topo.closed());
    // A closed genus-0 surface: V - E + F = 2 with welded V = 6n^2 + 2 (cube grid surface).
    const std::size_t faces = 12 * n * n, weldedVertices = 6 * n * n + 2;
    CHECK(topo.edges == faces * 3 / 2);
    CHECK(weldedVertices + faces == topo.edges + 2);
  }
  // Faces share their corners bit for bit, so even a zero tolerance welds them; moving one face
  // away opens the box.
  CHECK(analyseTopology(makeBox(glm::vec3(1.0f)), 0.0f).closed());
  Mesh opened = makeBox(glm::vec3(1.0f));
  for (std::size_t i = 0; i < 4; ++i) opened.positions[i].x += 1e-3f;  // the +x face
  CHECK(analyseTopology(opened).boundaryEdges == 8);
}

TEST_CASE("mesh_gen: sphere counts, radius, Euler characteristic 2") {
  const int slices = 24, stacks = 12;
  const Mesh m = makeSphere(2.5f, slices, stacks);
  CHECK(m.vertexCount() == std::size_t((stacks + 1) * (slices + 1)));
  CHECK(m.triangleCount() == std::size_t(2 * slices * (stacks - 1)));
  checkWellFormed(m);
  checkUvRange(m, 0.0f, 1.0f);
  checkOutward(m, glm::vec3(0.0f));
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    CHECK(glm::length(m.positions[i]) == doctest::Approx(2.5f).epsilon(1e-5));
    CHECK(glm::dot(m.normals[i], m.positions[i] / 2.5f) == doctest::Approx(1.0f).epsilon(1e-5));
  }
  const Topology topo = analyseTopology(m);
  CHECK(topo.closed());
  const std::size_t faces = m.triangleCount(), weldedVertices = slices * (stacks - 1) + 2;
  CHECK(topo.edges == faces * 3 / 2);
  CHECK(weldedVertices + faces == topo.edges + 2);
  CHECK_THROWS_AS(makeSphere(1.0f, 2, 8), std::invalid_argument);
  CHECK_THROWS_AS(makeSphere(1.0f, 8, 1), std::invalid_argument);
}

TEST_CASE("mesh_gen: torus counts, closed, genus 1") {
  const int segments = 30, sides = 10;
  const Mesh m = makeTorus(3.0f, 1.0f, segments, sides);
  CHECK(m.vertexCount() == std::size_t((segments + 1) * (sides + 1)));
  CHECK(m.triangleCount() == std::size_t(2 * segments * sides));
  checkWellFormed(m);
  checkUvRange(m, 0.0f, 1.0f);
  // Every point lies at distance r from the ring of radius R in the xz plane.
  for (const glm::vec3& p : m.positions) {
    const float ring = std::sqrt(p.x * p.x + p.z * p.z) - 3.0f;
    CHECK(std::sqrt(ring * ring + p.y * p.y) == doctest::Approx(1.0f).epsilon(1e-4));
  }
  const Topology topo = analyseTopology(m);
  CHECK(topo.closed());
  // V - E + F = 0 for a torus, with V = segments * sides after welding.
  CHECK(std::size_t(segments * sides) + m.triangleCount() == topo.edges);
}

TEST_CASE("mesh_gen: torus knot is closed, genus 1 and deterministic") {
  const int segments = 128, sides = 12;
  const Mesh m = makeTorusKnot(2, 3, 2.0f, 0.3f, segments, sides);
  CHECK(m.vertexCount() == std::size_t((segments + 1) * (sides + 1)));
  CHECK(m.triangleCount() == std::size_t(2 * segments * sides));
  checkWellFormed(m);
  const Topology topo = analyseTopology(m);
  CHECK(topo.closed());
  CHECK(std::size_t(segments * sides) + m.triangleCount() == topo.edges);
  // The curve stays within radius of the centre; the tube adds at most its own radius.
  const Aabb box = m.bounds();
  CHECK(glm::length(glm::max(glm::abs(box.min), glm::abs(box.max))) <= 2.0f * std::sqrt(3.0f) + 0.3f);
  CHECK(box.extent().x > 2.0f);  // and it is not collapsed
  CHECK(sameMesh(m, makeTorusKnot(2, 3, 2.0f, 0.3f, segments, sides)));
  // A (3,4) knot is a different shape with the same counts.
  CHECK_FALSE(sameMesh(m, makeTorusKnot(3, 4, 2.0f, 0.3f, segments, sides)));
  CHECK(analyseTopology(makeTorusKnot(3, 4, 2.0f, 0.2f, segments, sides)).closed());
}

TEST_CASE("mesh_gen: cylinder with and without caps") {
  const int s = 20;
  const Mesh capped = makeCylinder(0.5f, 3.0f, s, true);
  CHECK(capped.vertexCount() == std::size_t(4 * (s + 1)));
  CHECK(capped.triangleCount() == std::size_t(4 * s));
  checkWellFormed(capped);
  checkUvRange(capped, 0.0f, 1.0f);
  checkOutward(capped, glm::vec3(0.0f));
  CHECK(capped.bounds().min.y == -1.5f);
  CHECK(capped.bounds().max.y == 1.5f);
  const Topology closedTopo = analyseTopology(capped);
  CHECK(closedTopo.closed());
  // Genus 0, welded V = 2s rim vertices + 2 centres.
  CHECK(std::size_t(2 * s + 2) + capped.triangleCount() == closedTopo.edges + 2);

  const Mesh open = makeCylinder(0.5f, 3.0f, s, false);
  CHECK(open.vertexCount() == std::size_t(2 * (s + 1)));
  CHECK(open.triangleCount() == std::size_t(2 * s));
  checkWellFormed(open);
  const Topology openTopo = analyseTopology(open);
  CHECK(openTopo.boundaryEdges == std::size_t(2 * s));
  CHECK_FALSE(openTopo.closed());
}

TEST_CASE("mesh_gen: terrain heights come from terrainHeight, deterministic per seed") {
  const float size = 40.0f, scale = 5.0f;
  const int n = 32;
  const Mesh a = makeTerrain(size, n, scale, 7);
  CHECK(a.vertexCount() == std::size_t((n + 1) * (n + 1)));
  CHECK(a.triangleCount() == std::size_t(2 * n * n));
  checkWellFormed(a);
  checkUvRange(a, 0.0f, 1.0f);
  float lo = 1e30f, hi = -1e30f;
  for (std::size_t i = 0; i < a.vertexCount(); ++i) {
    const glm::vec3 p = a.positions[i];
    CHECK(p.y == terrainHeight(p.x, p.z, size, scale, 7));
    CHECK(a.normals[i].y > 0.0f);
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  CHECK(lo >= 0.0f);
  CHECK(hi <= scale);
  CHECK(hi - lo > 0.1f * scale);  // hills, not a flat sheet
  CHECK(a.bounds().min.x == -20.0f);
  CHECK(a.bounds().max.z == 20.0f);
  CHECK(sameMesh(a, makeTerrain(size, n, scale, 7)));
  CHECK_FALSE(sameMesh(a, makeTerrain(size, n, scale, 8)));
  const Topology topo = analyseTopology(a);
  CHECK(topo.boundaryEdges == std::size_t(4 * n));
  CHECK(topo.inconsistentEdges == 0);
}

TEST_CASE("mesh_gen: card is one quad facing +z with its base at the origin") {
  const Mesh m = makeCard(2.0f, 3.0f);
  CHECK(m.vertexCount() == 4);
  CHECK(m.triangleCount() == 2);
  checkWellFormed(m);
  checkUvRange(m, 0.0f, 1.0f);
  for (const glm::vec3& n : m.normals) CHECK(n == glm::vec3(0, 0, 1));
  CHECK(m.bounds().min == glm::vec3(-1.0f, 0.0f, 0.0f));
  CHECK(m.bounds().max == glm::vec3(1.0f, 3.0f, 0.0f));
  // The top edge samples image row 0 (v = 0).
  for (std::size_t i = 0; i < 4; ++i) CHECK(m.uvs[i].y == (m.positions[i].y > 0.0f ? 0.0f : 1.0f));
  CHECK(analyseTopology(m).boundaryEdges == 4);
}

TEST_CASE("mesh_gen: invalid tessellations are rejected with the parameter named") {
  CHECK_THROWS_AS(makePlane(1.0f, 0), std::invalid_argument);
  CHECK_THROWS_AS(makeBox(glm::vec3(1.0f), 0), std::invalid_argument);
  CHECK_THROWS_AS(makeTorus(1.0f, 0.2f, 2, 8), std::invalid_argument);
  CHECK_THROWS_AS(makeTorusKnot(0, 3, 1.0f, 0.2f), std::invalid_argument);
  CHECK_THROWS_AS(makeCylinder(1.0f, 1.0f, 2), std::invalid_argument);
  CHECK_THROWS_AS(makeTerrain(1.0f, 0, 1.0f, 1), std::invalid_argument);
  try {
    makeTorus(1.0f, 0.2f, 8, 1);
    FAIL("expected an exception");
  } catch (const std::invalid_argument& e) { CHECK(std::string(e.what()).find("sides") != std::string::npos); }
}

TEST_CASE("mesh: topology of a mesh far beyond any grid cell welds as near the origin") {
  // 1.5e19 / the weld epsilon is past 2^63: the cell index once overflowed its conversion
  // (undefined; found by fuzzing a model file). Two triangles sharing an edge, with a duplicated
  // vertex the weld must merge, at the origin and out there give the same topology.
  for (float at : {0.0f, 1.5e19f, -3e38f}) {
    CAPTURE(at);
    Mesh m;
    const float s = at == 0.0f ? 1.0f : std::abs(at) * 1e-3f;  // a size the floats can still tell apart
    m.positions = {{at, at, 0}, {at + s, at, 0}, {at, at + s, 0}, {at + s, at, 0}, {at + s, at + s, 0}};
    m.indices = {0, 1, 2, 2, 3, 4};  // vertex 3 repeats vertex 1: the shared edge 1-2 once welded
    const Topology t = analyseTopology(m);
    CHECK(t.edges == 5);
    CHECK(t.boundaryEdges == 4);
    CHECK(t.inconsistentEdges == 0);
  }
}

TEST_CASE("mesh: topology analysis on hand-made cases") {
  Mesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.indices = {0, 1, 2};
  Topology t = analyseTopology(tri);
  CHECK(t.edges == 3);
  CHECK(t.boundaryEdges == 3);
  CHECK_FALSE(t.closed());

  // Two triangles over one edge, the second wound the same way along it: a flipped neighbour.
  Mesh flipped;
  flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  flipped.indices = {0, 1, 2, 1, 2, 3};  // both walk 1 -> 2
  t = analyseTopology(flipped);
  CHECK(t.edges == 5);
  CHECK(t.inconsistentEdges == 1);
  flipped.indices = {0, 1, 2, 2, 1, 3};  // consistent: 1 -> 2, then 2 -> 1
  CHECK(analyseTopology(flipped).inconsistentEdges == 0);

  // Three triangles on one edge (a fin): non-manifold.
  Mesh fin;
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  t = analyseTopology(fin);
  CHECK(t.nonManifoldEdges == 1);
  CHECK_FALSE(t.closed());

  // Duplicated positions within the tolerance weld; farther ones do not.
  Mesh seam;
  seam.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.0f + 4e-6f, 0, 0}, {0, 1.0f - 4e-6f, 0}, {1, 1, 0}};
  seam.indices = {0, 1, 2, 4, 3, 5};
  CHECK(analyseTopology(seam, 1e-5f).edges == 5);
  CHECK(analyseTopology(seam, 1e-6f).edges == 6);
  // Collapsed triangles neither open nor close anything.
  Mesh box = makeBox(glm::vec3(1.0f));
  box.indices.insert(box.indices.end(), {0, 0, 1});
  CHECK(analyseTopology(box).closed());
  // An index past the vertices is ignored, never read.
  box.indices.insert(box.indices.end(), {0, 1, 999});
  CHECK(analyseTopology(box).closed());
}

TEST_CASE("mesh: append transforms positions and normals, and keeps mirrored faces front-facing") {
  Mesh m;
  const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), {10, 0, 0}), {1.0f, 4.0f, 1.0f});
  m.append(makeBox(glm::vec3(2.0f)), model);
  m.append(makeBox(glm::vec3(2.0f)));
  CHECK(m.vertexCount() == 48);
  CHECK(m.triangleCount() == 24);
  CHECK(m.bounds().min == glm::vec3(-1.0f, -4.0f, -1.0f));
  CHECK(m.bounds().max == glm::vec3(11.0f, 4.0f, 1.0f));
  checkWellFormed(m);
  // A sheared slab: the inverse transpose keeps normals perpendicular to the transformed faces.
  const glm::mat4 shear{1, 0, 0, 0, 0.5f, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // x += 0.5 y
  Mesh sheared;
  sheared.append(makeSphere(1.0f, 16, 8), shear);
  checkWellFormed(sheared);
  Mesh mirrored;
  mirrored.append(makeTorus(2.0f, 0.5f, 16, 8), glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f}));
  checkWellFormed(mirrored);
  CHECK(analyseTopology(mirrored).closed());
}

TEST_CASE("mesh_gen: inside-out and recomputed normals") {
  Mesh room = makeBox(glm::vec3(4.0f), 2);
  flipInsideOut(room);
  checkWellFormed(room);
  CHECK(analyseTopology(room).closed());
  for (std::size_t i = 0; i < room.vertexCount(); ++i)
    CHECK(glm::dot(room.normals[i], room.positions[i]) < 0.0f);  // pointing into the room

  Mesh sphere = makeSphere(1.0f, 32, 16);
  const std::vector<glm::vec3> analytic = sphere.normals;
  sphere.normals.assign(sphere.vertexCount(), glm::vec3(0.0f));
  computeSmoothNormals(sphere);
  std::size_t off = 0;
  for (std::size_t i = 0; i < analytic.size(); ++i) off += glm::dot(analytic[i], sphere.normals[i]) < 0.995f;
  CHECK(off == 0);
  checkWellFormed(sphere);
}

TEST_CASE("mesh_gen: noise is deterministic, bounded and seed-dependent") {
  SplitMix64 a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t va = a.next();
    CHECK(va == b.next());
    CHECK(va != c.next());
  }
  SplitMix64 r(1);
  for (int i = 0; i < 1000; ++i) {
    const float u = r.uniform();
    CHECK(u >= 0.0f);
    CHECK(u < 1.0f);
    const int k = r.below(7);
    CHECK(k >= 0);
    CHECK(k < 7);
  }
  // Lattice points take the hashed value exactly; the fBm stays in [0,1].
  CHECK(valueNoise(3.0f, 5.0f, 9) == float(hashCell(3, 5, 9) >> 40) * (1.0f / 16777215.0f));
  float lo = 1.0f, hi = 0.0f;
  for (int i = 0; i < 400; ++i) {
    const float v = fbmNoise(i * 0.37f, i * 0.11f, 5, 3);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  CHECK(lo >= 0.0f);
  CHECK(hi <= 1.0f);
  CHECK(hi - lo > 0.2f);
}

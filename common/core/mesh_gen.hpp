#pragma once
// Procedural meshes, deterministic (same arguments, same bytes on the same platform). Conventions
// of mesh.hpp: y up, counter-clockwise front faces, unit normals. Every shape is centred on the
// origin unless it says otherwise. Counts are exact and documented so tests can check them.
#include <cstdint>

#include <glm/glm.hpp>

#include "core/mesh.hpp"

namespace shadowlab {

// Square in the xz plane facing +y, `subdivisions` cells per side (>= 1); uvs span [0, uvRepeat].
// (n+1)^2 vertices, 2 n^2 triangles.
Mesh makePlane(float size, int subdivisions = 1, float uvRepeat = 1.0f);

// Axis-aligned box of full size `extents`, each face an n x n grid (n >= 1) with its own vertices
// so edges stay sharp; uvs [0,1] per face. 6 (n+1)^2 vertices, 12 n^2 triangles. Closed.
Mesh makeBox(const glm::vec3& extents, int subdivisions = 1);

// UV sphere: `slices` >= 3 around y, `stacks` >= 2 from pole to pole; seam and pole vertices are
// duplicated for uvs. (stacks+1)(slices+1) vertices, 2 slices (stacks-1) triangles. Closed.
Mesh makeSphere(float radius, int slices = 32, int stacks = 16);

// Torus around the y axis: ring radius R, tube radius r. (segments+1)(sides+1) vertices,
// 2 segments sides triangles. Closed.
Mesh makeTorus(float majorRadius, float minorRadius, int segments = 48, int sides = 16);

// (p,q) torus knot (p, q coprime; p=2, q=3 is the trefoil) scaled to about `radius` from the
// centre, swept by a tube of radius `tube`. Same counts as makeTorus. Closed.
Mesh makeTorusKnot(int p, int q, float radius, float tube, int segments = 256, int sides = 16);

// Cylinder along y from -height/2 to +height/2. Side: 2 (segments+1) vertices, 2 segments
// triangles; caps add 2 (segments+1) vertices (a centre and a rim each) and 2 segments
// triangles. Closed when capped.
Mesh makeCylinder(float radius, float height, int segments = 32, bool capped = true);

// Height field over the square [-size/2, size/2]^2 with `resolution` cells per side: heights are
// terrainHeight() at each vertex. (n+1)^2 vertices, 2 n^2 triangles; uvs span [0, 1].
Mesh makeTerrain(float size, int resolution, float heightScale, std::uint64_t seed);
// The terrain's height at world (x, z): fBm of value noise, in [0, heightScale]. Independent of
// the resolution, so objects can be placed on any tessellation of the same terrain.
float terrainHeight(float x, float z, float size, float heightScale, std::uint64_t seed);

// One quad in the xy plane facing +z, x in [-w/2, w/2], y in [0, h] (its base at the origin, so a
// card hangs from where it is placed); uvs [0,1] with v = 0 at the TOP edge (image row 0).
// Leaves and fences use it with a two-sided, alpha-tested material. 4 vertices, 2 triangles.
Mesh makeCard(float width, float height);

// ---- Deterministic randomness shared by the mesh, scene and texture generators. The standard
// distributions are implementation-defined, so a seed would give different scenes per compiler.
struct SplitMix64 {
  std::uint64_t state = 0;
  explicit SplitMix64(std::uint64_t seed) : state(seed) {}
  std::uint64_t next();
  float uniform();                    // [0, 1)
  float uniform(float lo, float hi);  // [lo, hi)
  int below(int n);                   // [0, n) for n >= 1
};
// A well-mixed hash of two lattice coordinates and a seed (value noise, per-cell choices).
std::uint64_t hashCell(std::int64_t x, std::int64_t y, std::uint64_t seed);
// 2D value noise in [0, 1] with a lattice spacing of 1, smooth (C1) between lattice points.
float valueNoise(float x, float y, std::uint64_t seed);
// Fractal sum of `octaves` value-noise layers (frequency x2, amplitude x0.5 each), in [0, 1].
float fbmNoise(float x, float y, int octaves, std::uint64_t seed);

// Area-weighted smooth normals; vertices at bit-identical positions (uv seams) share one normal.
void computeSmoothNormals(Mesh& mesh);
// Reverses winding and normals: a box seen from inside (rooms).
void flipInsideOut(Mesh& mesh);

}  // namespace shadowlab

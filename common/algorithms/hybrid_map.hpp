#pragma once
// Hybrid-resolution shadow maps (lesson 07; Li, Yang, Zhao, Chen, "Hybrid-resolution shadow mapping
// design and hard shadows anti-aliasing in special effects movies", Chinese Optics 9(1), 2016),
// GL-free: the reference the GPU passes of lessons/07_hybrid_maps/hybrid_maps are tested against, word
// for word, and what the lesson's exercises are graded on.
//
//   1. the merge sweep   a full-resolution depth map D (N x N), then bottom-up for `levels` levels:
//                        each 2x2 block of level k-1 texels D1..D4 with mean m becomes one level-k
//                        texel of depth m when every |m - Dn| passes the criterion (the paper's
//                        eq. 1: |m - Dn| / Dn <= eps0), else the four are kept. A block merges only
//                        when its four children are merged texels themselves (level 0 always is).
//   2. the index         the coarsest level is the root grid; a texel that did not merge owns a
//                        record of its four children's words, each a depth (a leaf) or a pointer to
//                        that child's own record. Records are in depth-first order over the
//                        quadtree, children in the order (x, y), (x+1, y), (x, y+1), (x+1, y+1), so
//                        a record's descendants follow it: their places come from a count pyramid
//                        (records per subtree) and a top-down prefix sum, as the GPU computes them.
//   3. the lookup        the source texel s = floor(uv N); the root word at s >> levels; while the
//                        word is a pointer, one level down: the child (s >> level) & 1 of the record.
//
// Words (32 bits, as the GPU stores them in R32UI / RGBA32UI textures): a leaf is the depth's float
// bits (depth >= 0, so the top bit is 0); a pointer is kPointer | record index.
//
// Conventions: grids are row-major, row 0 at v = 0 (shadow::DepthMap's), a level-k texel covers
// 2^k x 2^k source texels, sizes halve rounding up (a block at the border with children outside the
// grid never merges; a record's missing child is a leaf of depth 1, the far plane: lit).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/shadow_math.hpp"

namespace shadowlab::hybrid {

inline constexpr int kMaxLevels = 3;                    // the paper: two sweeps (2048 -> 1024 -> 512)
inline constexpr float kInternal = -1.0f;               // a merge-grid value: this texel did not merge
inline constexpr std::uint32_t kPointer = 0x80000000u;  // a word's flag: the rest is a record index

// ---- which depth the criterion reads --------------------------------------------------------------

// Window depth in [0,1] (what the map stores), linear depth, or the depth's derivative.
enum class Criterion { Window, Linear, Slope };

// How the light's window depth relates to distance, and how wide a source texel is.
struct DepthSpace {
  bool perspective = false;
  float nearZ = 0.0f, farZ = 1.0f;  // the light frustum's depth range (view-space distances)
  float texel = 0.0f;               // ortho: a source texel's world width; perspective: its width at distance 1
};
// From a light camera's projection (glm::ortho or glm::perspective) and a map of `size` texels.
// `texelWorld`: an orthographic camera's world texel (LightCamera::texelWorld). Throws
// std::invalid_argument for a projection that is neither, or a size below 1.
DepthSpace depthSpaceOf(const glm::mat4& projection, bool perspective, int size, float texelWorld);
// Linear depth of a window depth d: perspective, the eye distance 2 n f / ((f + n) - (2 d - 1)(f - n));
// orthographic, the distance from the near plane d (f - n). (For an orthographic light the
// relative test reads the same either way: linear depth is window depth times a constant.)
float linearDepth(float windowDepth, const DepthSpace& space);

struct MergeRule {
  Criterion criterion = Criterion::Window;
  float eps0 = 0.25f;     // Window, Linear: |m - Dn| <= eps0 Dn (the paper's 0.25)
  float maxSlope = 2.0f;  // Slope: max |m - Dn| <= maxSlope w / 2 (planes with |dz/dx| + |dz/dy| <= maxSlope)
  DepthSpace space;       // Linear and Slope read linear depth; Slope needs the texel width w
};

// One block: its four children (window depths, order (x,y), (x+1,y), (x,y+1), (x+1,y+1)) at level
// `level - 1`. The mean is ((D1 + D2) + (D3 + D4)) * 0.25 in float, in that order (the GPU does
// the same, `precise`). Merged when every child passes:
//   Window  |m - Dn| <= eps0 * Dn
//   Linear  the same on linear depths z: |mz - zn| <= eps0 * zn, mz their mean
//   Slope   |mz - zn| <= 0.5 * maxSlope * w, w the children's world width (2^(level-1) source
//           texels; times mz for a perspective light)
// A child that is kInternal (negative) or NaN never merges.
struct BlockMerge {
  bool merged = false;
  float mean = 0.0f;  // the window-depth mean (stored when merged)
};
BlockMerge mergeBlock(const std::array<float, 4>& children, const MergeRule& rule, int level);

// ---- 1. the merge sweep ---------------------------------------------------------------------------

// One level of the merge pyramid: the mean of each merged texel, kInternal where it did not merge.
struct MergeGrid {
  int size = 0;
  std::vector<float> value;  // size * size, row-major, row 0 at v = 0
  float at(int x, int y) const { return value[std::size_t(y) * std::size_t(size) + std::size_t(x)]; }
};
int halvedSize(int size);  // (size + 1) / 2
// Level `level` from level `level - 1` (`children`): ceil(size / 2) texels a side.
MergeGrid sweepLevel(const MergeGrid& children, const MergeRule& rule, int level);
// Levels 0 (the source map itself) to `levels`. Throws std::invalid_argument for levels outside
// 0..kMaxLevels or a map that is not square.
std::vector<MergeGrid> mergeSweep(const shadow::DepthMap& source, const MergeRule& rule, int levels);

// ---- 2. the index ---------------------------------------------------------------------------------

// The count pyramid and the record starts, from level 1 up to a single texel (top). counts[k][t]:
// records in the subtree of texel t at level k (itself when it did not merge and k <= levels, then
// its children's); starts[k][t]: the index of its first record (its own, when it has one).
struct IndexPyramid {
  std::vector<int> sizes;                          // sizes[k], k = 0 .. top
  std::vector<std::vector<std::uint32_t>> counts;  // [k], k = 1 .. top ([0] empty)
  std::vector<std::vector<std::uint32_t>> starts;  // [k], k = 1 .. top ([0] empty)
  int top() const { return int(sizes.size()) - 1; }
  std::uint32_t records() const { return counts.size() > 1 ? counts.back()[0] : 0u; }
};
IndexPyramid indexPyramid(const std::vector<MergeGrid>& merged);

struct HybridMap {
  int sourceSize = 0;                                 // N
  int levels = 0;                                     // L: the root grid is level L
  int rootSize = 0;                                   // ceil(N / 2^L)
  std::vector<std::uint32_t> root;                    // rootSize^2 words, row-major, row 0 at v = 0
  std::vector<std::array<std::uint32_t, 4>> records;  // depth-first; child i at (x + (i & 1), y + (i >> 1))
  std::uint32_t rootWord(int x, int y) const { return root[std::size_t(y) * std::size_t(rootSize) + std::size_t(x)]; }
};
std::uint32_t leafWord(float depth);  // the float's bits (depth >= 0)
inline bool isPointer(std::uint32_t word) { return (word & kPointer) != 0u; }
inline std::uint32_t recordIndex(std::uint32_t word) { return word & ~kPointer; }
float leafDepth(std::uint32_t word);
// The stored map from the merge pyramid (levels = merged.size() - 1). Throws std::invalid_argument
// when there are more records than a pointer can name (2^31).
HybridMap buildHybrid(const std::vector<MergeGrid>& merged);
HybridMap buildHybrid(const shadow::DepthMap& source, const MergeRule& rule, int levels);

// ---- 3. the lookup --------------------------------------------------------------------------------

struct Descent {
  float depth = 1.0f;  // the finest stored depth over the source texel
  int level = 0;       // the level it was stored at (0: full resolution)
  int steps = 0;       // pointers followed (0 .. levels)
};
// Source texel (sx, sy), clamped into the map. Throws std::runtime_error for a pointer to a record
// that does not exist (a corrupt map).
Descent descend(const HybridMap& map, int sx, int sy);
// The depth bias for a texel stored at `level`: the slope-scaled part and its clamp grow with the
// texel's width, 2^level source texels (a tilted receiver is that much farther from the stored
// mean); the constant part, the depth format's precision, does not:
//   min(constant + slope tan(theta) 2^level, maxBias 2^level), maxBias 2^level when cosTheta <= 0.
// Level 0 is shadow::slopeScaledBias.
float levelBias(float constant, float slope, float maxBias, float cosTheta, int level);
// The paper's shadow test (its Algorithm 2) at uvz = (u, v, window depth), GL_NEAREST: lit (1) when
// depth - levelBias(...) <= the stored depth, with the level of the texel actually read; outside
// [0,1]^2 or beyond the far plane (depth > 1) the light knows nothing: lit.
struct Bias {
  float constant = 0.0f, slope = 0.0f, maxBias = 0.0f;
};
float hybridLookup(const HybridMap& map, const glm::vec3& uvz, const Bias& bias, float cosTheta);

// ---- what it costs --------------------------------------------------------------------------------

struct HybridCounts {
  std::uint64_t rootWords = 0, records = 0;
  std::uint64_t storedTexels = 0;                              // leaves: the depths the map holds
  std::array<std::uint64_t, kMaxLevels + 1> sourceTexelsAt{};  // source texels resolved at level k
  std::array<std::uint64_t, kMaxLevels + 1> leavesAt{};        // leaves stored at level k
  std::array<std::uint64_t, kMaxLevels + 1> recordsAt{};       // records owned by level-k texels
};
HybridCounts countHybrid(const HybridMap& map);
// Bytes of the stored map as the GPU holds it: 4 per root word, and the record texture of
// `recordRowWidth` records (16 bytes each) a row, its last row allocated whole (no texture when
// there are no records). recordRowWidth 0: exactly 16 bytes per record.
// (Border blocks count whole in sourceTexelsAt: a size that does not halve evenly overcounts.)
std::uint64_t storedBytes(const HybridMap& map, int recordRowWidth);

}  // namespace shadowlab::hybrid

#include "algorithms/hybrid_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace shadowlab::hybrid {

// ---- which depth the criterion reads --------------------------------------------------------------

DepthSpace depthSpaceOf(const glm::mat4& P, bool perspective, int size, float texelWorld) {
  if (size < 1) throw std::invalid_argument("depthSpaceOf: map size " + std::to_string(size) + " is below 1");
  DepthSpace s;
  s.perspective = perspective;
  if (perspective) {
    // glm::perspective: P[2][2] = -(f + n) / (f - n), P[3][2] = -2 f n / (f - n), P[2][3] = -1.
    if (P[2][3] != -1.0f || P[1][1] <= 0.0f) throw std::invalid_argument("depthSpaceOf: not a perspective projection");
    s.nearZ = P[3][2] / (P[2][2] - 1.0f);
    s.farZ = P[3][2] / (P[2][2] + 1.0f);
    s.texel = 2.0f / (P[1][1] * float(size));  // 2 tan(fov / 2) / size
  } else {
    // glm::ortho: P[2][2] = -2 / (f - n), P[3][2] = -(f + n) / (f - n), P[3][3] = 1.
    if (P[3][3] != 1.0f || P[2][2] == 0.0f) throw std::invalid_argument("depthSpaceOf: not an orthographic projection");
    const float range = -2.0f / P[2][2];
    const float sum = -P[3][2] * range;
    s.nearZ = 0.5f * (sum - range);
    s.farZ = 0.5f * (sum + range);
    s.texel = texelWorld;
  }
  return s;
}

float linearDepth(float d, const DepthSpace& s) {
  const float range = s.farZ - s.nearZ;
  if (!s.perspective) return d * range;
  const float ndc = 2.0f * d - 1.0f;
  return (2.0f * s.nearZ * s.farZ) / ((s.farZ + s.nearZ) - ndc * range);
}

namespace {

float mean4(const std::array<float, 4>& d) { return ((d[0] + d[1]) + (d[2] + d[3])) * 0.25f; }

bool relativeClose(const std::array<float, 4>& d, float m, float eps0) {
  for (float dn : d)
    if (!(std::fabs(m - dn) <= eps0 * dn)) return false;
  return true;
}

bool slopeClose(const std::array<float, 4>& z, float mz, float halfWidth) {
  for (float zn : z)
    if (!(std::fabs(mz - zn) <= halfWidth)) return false;
  return true;
}

}  // namespace

BlockMerge mergeBlock(const std::array<float, 4>& d, const MergeRule& rule, int level) {
  BlockMerge out;
  for (float dn : d)
    if (!(dn >= 0.0f)) return out;  // a child that did not merge (kInternal), or NaN
  out.mean = mean4(d);
  if (rule.criterion == Criterion::Window) {
    out.merged = relativeClose(d, out.mean, rule.eps0);
    return out;
  }
  std::array<float, 4> z;
  for (int i = 0; i < 4; ++i) z[std::size_t(i)] = linearDepth(d[std::size_t(i)], rule.space);
  const float mz = mean4(z);
  if (rule.criterion == Criterion::Linear) {
    out.merged = relativeClose(z, mz, rule.eps0);
    return out;
  }
  // The children's width: 2^(level - 1) source texels (at distance mz for a perspective light).
  const float texels = std::ldexp(1.0f, level - 1);
  const float width = (rule.space.perspective ? mz * rule.space.texel : rule.space.texel) * texels;
  out.merged = slopeClose(z, mz, 0.5f * rule.maxSlope * width);
  return out;
}

// ---- 1. the merge sweep ---------------------------------------------------------------------------

int halvedSize(int size) { return (size + 1) / 2; }

MergeGrid sweepLevel(const MergeGrid& c, const MergeRule& rule, int level) {
  MergeGrid out;
  out.size = halvedSize(c.size);
  out.value.assign(std::size_t(out.size) * std::size_t(out.size), kInternal);
  for (int y = 0; y < out.size; ++y)
    for (int x = 0; x < out.size; ++x) {
      if (2 * x + 1 >= c.size || 2 * y + 1 >= c.size) continue;  // a block cut by the border
      const std::array<float, 4> d = {c.at(2 * x, 2 * y), c.at(2 * x + 1, 2 * y), c.at(2 * x, 2 * y + 1),
                                      c.at(2 * x + 1, 2 * y + 1)};
      const BlockMerge b = mergeBlock(d, rule, level);
      if (b.merged) out.value[std::size_t(y) * std::size_t(out.size) + std::size_t(x)] = b.mean;
    }
  return out;
}

std::vector<MergeGrid> mergeSweep(const shadow::DepthMap& source, const MergeRule& rule, int levels) {
  if (levels < 0 || levels > kMaxLevels)
    throw std::invalid_argument("hybrid map: levels = " + std::to_string(levels) + " is not in 0.." +
                                std::to_string(kMaxLevels));
  if (source.width != source.height || source.width < 1)
    throw std::invalid_argument("hybrid map: the source map is " + std::to_string(source.width) + "x" +
                                std::to_string(source.height) + ", not square");
  std::vector<MergeGrid> grids(1);
  grids[0].size = source.width;
  grids[0].value = source.depth;
  for (int k = 1; k <= levels; ++k) grids.push_back(sweepLevel(grids.back(), rule, k));
  return grids;
}

// ---- 2. the index ---------------------------------------------------------------------------------

namespace {

// Whether texel t of level k (1 <= k <= levels) did not merge and so owns a record.
bool ownsRecord(const std::vector<MergeGrid>& merged, int k, std::size_t t) {
  return k >= 1 && k < int(merged.size()) && !(merged[std::size_t(k)].value[t] >= 0.0f);
}

std::uint32_t childCount(const IndexPyramid& p, int k, int x, int y) {
  if (k < 1 || x >= p.sizes[std::size_t(k)] || y >= p.sizes[std::size_t(k)]) return 0u;
  return p.counts[std::size_t(k)][std::size_t(y) * std::size_t(p.sizes[std::size_t(k)]) + std::size_t(x)];
}

}  // namespace

IndexPyramid indexPyramid(const std::vector<MergeGrid>& merged) {
  IndexPyramid p;
  p.sizes.push_back(merged.at(0).size);
  while (p.sizes.back() > 1 || int(p.sizes.size()) < int(merged.size())) p.sizes.push_back(halvedSize(p.sizes.back()));
  const int top = p.top();
  p.counts.resize(std::size_t(top) + 1);
  p.starts.resize(std::size_t(top) + 1);
  // Up: records per subtree.
  for (int k = 1; k <= top; ++k) {
    const int n = p.sizes[std::size_t(k)];
    auto& counts = p.counts[std::size_t(k)];
    counts.assign(std::size_t(n) * std::size_t(n), 0u);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::size_t t = std::size_t(y) * std::size_t(n) + std::size_t(x);
        const bool own = ownsRecord(merged, k, t);
        if (k < int(merged.size()) && !own) continue;  // merged: no records below it
        std::uint32_t sum = own ? 1u : 0u;
        for (int i = 0; i < 4; ++i) sum += childCount(p, k - 1, 2 * x + (i & 1), 2 * y + (i >> 1));
        counts[t] = sum;
      }
  }
  // Down: each texel's first record, after its parent's own and its earlier siblings' subtrees.
  p.starts[std::size_t(top)].assign(1, 0u);
  for (int k = top - 1; k >= 1; --k) {
    const int n = p.sizes[std::size_t(k)], np = p.sizes[std::size_t(k) + 1];
    auto& starts = p.starts[std::size_t(k)];
    starts.assign(std::size_t(n) * std::size_t(n), 0u);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::size_t parent = std::size_t(y / 2) * std::size_t(np) + std::size_t(x / 2);
        std::uint32_t s = p.starts[std::size_t(k) + 1][parent] + (ownsRecord(merged, k + 1, parent) ? 1u : 0u);
        const int sibling = (x & 1) + 2 * (y & 1);
        for (int j = 0; j < sibling; ++j) s += childCount(p, k, (x & ~1) + (j & 1), (y & ~1) + (j >> 1));
        starts[std::size_t(y) * std::size_t(n) + std::size_t(x)] = s;
      }
  }
  return p;
}

// The float's bits as they are (std::bit_cast, which the browser build's libc++ lacks; memcpy is
// the same copy and compiles to the same move).
std::uint32_t leafWord(float depth) {
  std::uint32_t word;
  std::memcpy(&word, &depth, sizeof word);
  return word;
}
float leafDepth(std::uint32_t word) {
  float depth;
  std::memcpy(&depth, &word, sizeof depth);
  return depth;
}

namespace {

// The word level k stores for texel (x, y): its depth, a pointer to its record, or (outside the
// grid) the far plane.
std::uint32_t wordAt(const std::vector<MergeGrid>& merged, const IndexPyramid& p, int k, int x, int y) {
  const MergeGrid& g = merged[std::size_t(k)];
  if (x >= g.size || y >= g.size) return leafWord(1.0f);
  const std::size_t t = std::size_t(y) * std::size_t(g.size) + std::size_t(x);
  if (g.value[t] >= 0.0f || k == 0) return leafWord(g.value[t]);
  return kPointer | p.starts[std::size_t(k)][t];
}

}  // namespace

HybridMap buildHybrid(const std::vector<MergeGrid>& merged) {
  const IndexPyramid p = indexPyramid(merged);
  if (p.records() >= kPointer) throw std::invalid_argument("hybrid map: too many records for a 31-bit index");
  HybridMap map;
  map.sourceSize = merged[0].size;
  map.levels = int(merged.size()) - 1;
  map.rootSize = merged.back().size;
  map.root.resize(std::size_t(map.rootSize) * std::size_t(map.rootSize));
  for (int y = 0; y < map.rootSize; ++y)
    for (int x = 0; x < map.rootSize; ++x)
      map.root[std::size_t(y) * std::size_t(map.rootSize) + std::size_t(x)] = wordAt(merged, p, map.levels, x, y);
  map.records.resize(p.records());
  for (int k = 1; k <= map.levels; ++k) {
    const MergeGrid& g = merged[std::size_t(k)];
    for (int y = 0; y < g.size; ++y)
      for (int x = 0; x < g.size; ++x) {
        const std::size_t t = std::size_t(y) * std::size_t(g.size) + std::size_t(x);
        if (!ownsRecord(merged, k, t)) continue;
        auto& record = map.records[p.starts[std::size_t(k)][t]];
        for (int i = 0; i < 4; ++i)
          record[std::size_t(i)] = wordAt(merged, p, k - 1, 2 * x + (i & 1), 2 * y + (i >> 1));
      }
  }
  return map;
}

HybridMap buildHybrid(const shadow::DepthMap& source, const MergeRule& rule, int levels) {
  return buildHybrid(mergeSweep(source, rule, levels));
}

// ---- 3. the lookup --------------------------------------------------------------------------------

Descent descend(const HybridMap& map, int sx, int sy) {
  sx = std::clamp(sx, 0, map.sourceSize - 1);
  sy = std::clamp(sy, 0, map.sourceSize - 1);
  Descent d;
  d.level = map.levels;
  std::uint32_t word = map.rootWord(sx >> map.levels, sy >> map.levels);
  while (isPointer(word) && d.level > 0) {
    const std::uint32_t r = recordIndex(word);
    if (r >= map.records.size())
      throw std::runtime_error("hybrid map: a pointer to record " + std::to_string(r) + " of " +
                               std::to_string(map.records.size()));
    --d.level;
    word = map.records[r][std::size_t(((sx >> d.level) & 1) + 2 * ((sy >> d.level) & 1))];
    ++d.steps;
  }
  d.depth = leafDepth(word);
  return d;
}

// Lesson 03's slope-scaled bias with the slope and its clamp scaled by the texel's width (a power
// of two: the scaling is exact), so level 0 is shadow::slopeScaledBias itself.
float levelBias(float constant, float slope, float maxBias, float cosTheta, int level) {
  const float scale = std::ldexp(1.0f, level);
  return shadow::slopeScaledBias(constant, slope * scale, cosTheta, maxBias * scale);
}

float hybridLookup(const HybridMap& map, const glm::vec3& uvz, const Bias& bias, float cosTheta) {
  if (uvz.x < 0.0f || uvz.x > 1.0f || uvz.y < 0.0f || uvz.y > 1.0f || uvz.z > 1.0f) return 1.0f;
  const float n = float(map.sourceSize);
  const Descent d = descend(map, int(std::floor(uvz.x * n)), int(std::floor(uvz.y * n)));
  return uvz.z - levelBias(bias.constant, bias.slope, bias.maxBias, cosTheta, d.level) <= d.depth ? 1.0f : 0.0f;
}

// ---- what it costs --------------------------------------------------------------------------------

namespace {

void countWord(const HybridMap& map, std::uint32_t word, int level, HybridCounts& c) {
  if (!isPointer(word) || level == 0) {
    ++c.storedTexels;
    ++c.leavesAt[std::size_t(level)];
    c.sourceTexelsAt[std::size_t(level)] += std::uint64_t(1) << (2 * level);
    return;
  }
  ++c.recordsAt[std::size_t(level)];
  for (std::uint32_t child : map.records.at(recordIndex(word))) countWord(map, child, level - 1, c);
}

}  // namespace

HybridCounts countHybrid(const HybridMap& map) {
  HybridCounts c;
  c.rootWords = map.root.size();
  c.records = map.records.size();
  for (std::uint32_t word : map.root) countWord(map, word, map.levels, c);
  return c;
}

std::uint64_t storedBytes(const HybridMap& map, int rowWidth) {
  const std::uint64_t records = map.records.size();
  std::uint64_t allocated = records;
  if (rowWidth > 0) {
    const std::uint64_t w = std::uint64_t(rowWidth);
    allocated = (records + w - 1) / w * w;
  }
  return 4 * std::uint64_t(map.root.size()) + 16 * allocated;
}

}  // namespace shadowlab::hybrid

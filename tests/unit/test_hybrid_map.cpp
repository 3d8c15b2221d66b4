// algorithms/hybrid_map: hybrid-resolution shadow maps (lesson 07). The merge criterion, the sweep
// and the index on maps small enough to work out by hand, then randomised maps checked against an
// independent top-down build of the same quadtree.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/hybrid_map.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::hybrid;

namespace {

MergeRule windowRule(float eps0) {
  MergeRule r;
  r.eps0 = eps0;
  return r;
}

// Window depth of eye distance z in a perspective frustum (n, f): the inverse of linearDepth.
float windowOf(float z, float n, float f) { return 0.5f * (((f + n) - 2.0f * n * f / z) / (f - n)) + 0.5f; }

// The 4x4 map of the hand-worked example: flat at 0.5 except one 2x2 block holding a step.
shadow::DepthMap stepMap() {
  return shadow::DepthMap(4, 4,
                          {0.5f, 0.5f, 0.5f, 0.5f,  //
                           0.5f, 0.5f, 0.5f, 0.5f,  //
                           0.5f, 0.5f, 0.9f, 0.9f,  //
                           0.5f, 0.5f, 0.9f, 0.1f});
}

}  // namespace

TEST_CASE("hybrid: the paper's criterion (window depth) on one block") {
  // All equal: merged into their mean even with eps0 = 0.
  BlockMerge b = mergeBlock({0.5f, 0.5f, 0.5f, 0.5f}, windowRule(0.0f), 1);
  CHECK(b.merged);
  CHECK(b.mean == 0.5f);
  // A tower top at 0.6 beside the ground at 0.75: m = 0.675, |m - 0.6| = 0.075 <= 0.25 * 0.6 and
  // |m - 0.75| = 0.075 <= 0.25 * 0.75: eps0 = 0.25 merges a 15 % depth step (the silhouette goes).
  b = mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, windowRule(0.25f), 1);
  CHECK(b.merged);
  CHECK(b.mean == doctest::Approx(0.675f));
  // eps0 = 0.1: 0.075 > 0.1 * 0.6 = 0.06, kept.
  CHECK_FALSE(mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, windowRule(0.1f), 1).merged);
  // A near caster in one texel: m = 0.7, |0.7 - 0.1| = 0.6 > 0.25 * 0.1.
  CHECK_FALSE(mergeBlock({0.1f, 0.9f, 0.9f, 0.9f}, windowRule(0.25f), 1).merged);
  // A child that did not merge at the level below stops its parent, whatever the values.
  CHECK_FALSE(mergeBlock({kInternal, 0.5f, 0.5f, 0.5f}, windowRule(1.0f), 2).merged);
  CHECK_FALSE(mergeBlock({std::nanf(""), 0.5f, 0.5f, 0.5f}, windowRule(1.0f), 1).merged);
  // The mean is ((D1 + D2) + (D3 + D4)) / 4 in that order.
  const float d[4] = {0.1f, 0.2f, 0.3f, 0.7f};
  CHECK(mergeBlock({d[0], d[1], d[2], d[3]}, windowRule(10.0f), 1).mean == ((d[0] + d[1]) + (d[2] + d[3])) * 0.25f);
}

TEST_CASE("hybrid: linear depth undoes the perspective's crowding near 1") {
  // n = 1, f = 100: eye distances 10 and 20 land at window depths 0.909 and 0.960.
  DepthSpace space{true, 1.0f, 100.0f, 0.001f};
  const float d10 = windowOf(10.0f, 1.0f, 100.0f), d20 = windowOf(20.0f, 1.0f, 100.0f);
  CHECK(d10 == doctest::Approx(0.909091f));
  CHECK(d20 == doctest::Approx(0.959596f));
  CHECK(linearDepth(d10, space) == doctest::Approx(10.0f).epsilon(1e-4));
  CHECK(linearDepth(d20, space) == doctest::Approx(20.0f).epsilon(1e-4));
  CHECK(linearDepth(0.0f, space) == doctest::Approx(1.0f));
  CHECK(linearDepth(1.0f, space) == doctest::Approx(100.0f));
  // A caster at 10 m over a receiver at 20 m: in window depth m = 0.934, |m - d10| = 0.025 is far
  // below 0.25 * 0.909, so the paper's criterion merges it; in linear depth mz = 15 and
  // |15 - 10| = 5 > 0.25 * 10: kept.
  MergeRule rule = windowRule(0.25f);
  rule.space = space;
  CHECK(mergeBlock({d10, d10, d20, d20}, rule, 1).merged);
  rule.criterion = Criterion::Linear;
  CHECK_FALSE(mergeBlock({d10, d10, d20, d20}, rule, 1).merged);
  // The stored value is still the window depths' mean (what the lookup compares against).
  rule.eps0 = 1.0f;
  CHECK(mergeBlock({d10, d10, d20, d20}, rule, 1).mean == doctest::Approx(0.5f * (d10 + d20)));
}

TEST_CASE("hybrid: an orthographic light's linear depth is window depth times the range") {
  const DepthSpace space = depthSpaceOf(glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 2.0f, 102.0f), false, 100, 0.1f);
  CHECK(space.nearZ == doctest::Approx(2.0f));
  CHECK(space.farZ == doctest::Approx(102.0f));
  CHECK(space.texel == 0.1f);
  CHECK(linearDepth(0.25f, space) == doctest::Approx(25.0f));
  // So the relative test reads the same in both: the same blocks merge.
  std::mt19937_64 rng(test::seedFor("hybrid.ortho_linear"));
  std::uniform_real_distribution<float> u(0.05f, 1.0f);
  MergeRule window = windowRule(0.1f), linear = windowRule(0.1f);
  window.space = linear.space = space;
  linear.criterion = Criterion::Linear;
  int disagree = 0, merged = 0;
  for (int i = 0; i < 2000; ++i) {
    const float base = u(rng), step = 0.15f * u(rng);
    const std::array<float, 4> d = {base, base + step * u(rng), base, base + step * u(rng)};
    const bool w = mergeBlock(d, window, 1).merged;
    merged += w;
    disagree += w != mergeBlock(d, linear, 1).merged;
  }
  INFO("seed ", test::seed());
  CHECK(merged > 200);  // the sample has both kinds of block
  CHECK(merged < 1800);
  CHECK(disagree <= 4);  // only where rounding decides a block within one ulp of the threshold
}

TEST_CASE("hybrid: depthSpaceOf reads a perspective frustum back") {
  const DepthSpace s = depthSpaceOf(glm::perspective(glm::radians(90.0f), 1.0f, 0.5f, 150.0f), true, 1024, 0);
  CHECK(s.nearZ == doctest::Approx(0.5f));
  CHECK(s.farZ == doctest::Approx(150.0f).epsilon(1e-4));
  CHECK(s.texel == doctest::Approx(2.0f / 1024.0f));  // 2 tan(45 degrees) / 1024
  CHECK_THROWS_AS(depthSpaceOf(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 2.0f), true, 8, 0), std::invalid_argument);
  CHECK_THROWS_AS(depthSpaceOf(glm::mat4(1.0f), false, 0, 0), std::invalid_argument);
}

TEST_CASE("hybrid: the slope criterion bounds the depth's derivative") {
  // Orthographic, a source texel 0.1 m wide, 100 m of depth. A plane rising 1 m per metre along x:
  // children 0.1 m apart differ by 0.1 m, mz is 0.05 m from each: |dz/dx| + |dz/dy| = 1.
  MergeRule rule;
  rule.criterion = Criterion::Slope;
  rule.space = {false, 0.0f, 100.0f, 0.1f};
  const std::array<float, 4> plane = {0.050f, 0.051f, 0.050f, 0.051f};
  rule.maxSlope = 2.0f;  // allowed: 0.5 * 2 * 0.1 = 0.1 m >= 0.05 m
  CHECK(mergeBlock(plane, rule, 1).merged);
  rule.maxSlope = 0.5f;  // 0.025 m < 0.05 m
  CHECK_FALSE(mergeBlock(plane, rule, 1).merged);
  // Higher up the children are wider (level 3: four source texels): the same depths, a quarter
  // of the slope. 0.5 * 0.5 * 0.4 = 0.1 m >= 0.05 m.
  CHECK(mergeBlock(plane, rule, 3).merged);
  rule.maxSlope = 0.9f;
  CHECK_FALSE(mergeBlock(plane, rule, 1).merged);  // 0.045 m < 0.05 m
  CHECK(mergeBlock(plane, rule, 2).merged);        // 0.09 m >= 0.05 m
  // A perspective light's texel widens with distance: w = mz * texel.
  rule.space = {true, 1.0f, 100.0f, 0.01f};
  const float a = windowOf(10.0f, 1.0f, 100.0f), b = windowOf(10.1f, 1.0f, 100.0f);
  rule.maxSlope = 1.1f;  // w = 10.05 * 0.01, allowed 0.5 * 1.1 * 0.1005 = 0.055 >= 0.05
  CHECK(mergeBlock({a, b, a, b}, rule, 1).merged);
  rule.maxSlope = 0.9f;
  CHECK_FALSE(mergeBlock({a, b, a, b}, rule, 1).merged);
}

TEST_CASE("hybrid: the sweep and the index of a 4x4 map, by hand") {
  // eps0 = 0.01: the three flat blocks merge (level 1: 0.5, 0.5, 0.5 and one kept); the level-2
  // block has a child that did not merge, so it is kept too.
  const std::vector<MergeGrid> grids = mergeSweep(stepMap(), windowRule(0.01f), 2);
  REQUIRE(grids.size() == 3);
  CHECK(grids[1].size == 2);
  CHECK(grids[1].value == std::vector<float>{0.5f, 0.5f, 0.5f, kInternal});
  CHECK(grids[2].value == std::vector<float>{kInternal});

  // Records in depth-first order: the root texel's (0), then level-1 texel (1, 1)'s (1).
  const IndexPyramid p = indexPyramid(grids);
  CHECK(p.top() == 2);
  CHECK(p.counts[1] == std::vector<std::uint32_t>{0, 0, 0, 1});
  CHECK(p.counts[2] == std::vector<std::uint32_t>{2});
  CHECK(p.starts[1][3] == 1u);
  CHECK(p.records() == 2u);

  const HybridMap map = buildHybrid(grids);
  CHECK(map.rootSize == 1);
  CHECK(map.root == std::vector<std::uint32_t>{kPointer | 0u});
  REQUIRE(map.records.size() == 2);
  CHECK(map.records[0] == std::array<std::uint32_t, 4>{leafWord(0.5f), leafWord(0.5f), leafWord(0.5f), kPointer | 1u});
  CHECK(map.records[1] == std::array<std::uint32_t, 4>{leafWord(0.9f), leafWord(0.9f), leafWord(0.9f), leafWord(0.1f)});

  // Descents: (3, 3) follows both pointers to the full-resolution 0.1; (0, 0) stops at level 1.
  Descent d = descend(map, 3, 3);
  CHECK(d.depth == 0.1f);
  CHECK(d.level == 0);
  CHECK(d.steps == 2);
  d = descend(map, 0, 0);
  CHECK(d.depth == 0.5f);
  CHECK(d.level == 1);
  CHECK(d.steps == 1);
  CHECK(descend(map, 2, 3).depth == 0.9f);

  // 7 depths stored (3 at level 1, 4 at level 0) in 1 root word and 2 records: 36 bytes, against
  // 64 for the full map of 16 floats.
  const HybridCounts c = countHybrid(map);
  CHECK(c.storedTexels == 7u);
  CHECK(c.leavesAt[1] == 3u);
  CHECK(c.leavesAt[0] == 4u);
  CHECK(c.sourceTexelsAt[1] == 12u);
  CHECK(c.sourceTexelsAt[0] == 4u);
  CHECK(storedBytes(map, 0) == 36u);
  CHECK(storedBytes(map, 4) == 4u + 64u);  // one row of 4 records allocated whole
}

TEST_CASE("hybrid: the bias grows with the level read, all but its constant part") {
  // 60 degrees: tan = sqrt(3). Level 0 is the standard map's slope-scaled bias.
  const float c = 0.5f, tan60 = std::sqrt(3.0f);
  CHECK(levelBias(0.001f, 0.002f, 1.0f, c, 0) == doctest::Approx(shadow::slopeScaledBias(0.001f, 0.002f, c, 1.0f)));
  CHECK(levelBias(0.001f, 0.002f, 1.0f, c, 0) == doctest::Approx(0.001f + 0.002f * tan60));
  CHECK(levelBias(0.001f, 0.002f, 1.0f, c, 2) == doctest::Approx(0.001f + 4.0f * 0.002f * tan60));
  CHECK(levelBias(0.001f, 0.002f, 0.003f, c, 0) == doctest::Approx(0.003f));     // clamped
  CHECK(levelBias(0.001f, 0.002f, 0.003f, c, 1) == doctest::Approx(0.006f));     // the clamp doubles too
  CHECK(levelBias(0.001f, 0.002f, 0.003f, 0.0f, 3) == doctest::Approx(0.024f));  // grazing: the clamp
  CHECK(levelBias(0.001f, 0.0f, 0.003f, 1.0f, 3) == doctest::Approx(0.001f));    // the constant stays
}

TEST_CASE("hybrid: the lookup compares against the texel it reaches, its bias grown with the level") {
  const HybridMap map = buildHybrid(stepMap(), windowRule(0.01f), 2);
  // (0.9, 0.9) is texel (3, 3): 0.1 at level 0. (0.1, 0.1) is texel (0, 0): 0.5 at level 1.
  const Bias none;
  CHECK(hybridLookup(map, {0.9f, 0.9f, 0.1f}, none, 1.0f) == 1.0f);
  CHECK(hybridLookup(map, {0.9f, 0.9f, 0.2f}, none, 1.0f) == 0.0f);
  CHECK(hybridLookup(map, {0.1f, 0.1f, 0.52f}, none, 1.0f) == 0.0f);
  // Slope 0.01 at 45 degrees (tan 1): 0.01 at level 0, 0.02 at level 1.
  const Bias slope{0.0f, 0.01f, 1.0f};
  const float cos45 = std::sqrt(0.5f);
  CHECK(hybridLookup(map, {0.1f, 0.1f, 0.515f}, slope, cos45) == 1.0f);  // 0.515 - 0.02 <= 0.5
  CHECK(hybridLookup(map, {0.9f, 0.9f, 0.115f}, slope, cos45) == 0.0f);  // 0.115 - 0.01 > 0.1
  // Outside the map or beyond the far plane: lit.
  CHECK(hybridLookup(map, {-0.1f, 0.5f, 0.99f}, none, 1.0f) == 1.0f);
  CHECK(hybridLookup(map, {0.5f, 1.2f, 0.99f}, none, 1.0f) == 1.0f);
  CHECK(hybridLookup(map, {0.9f, 0.9f, 1.01f}, none, 1.0f) == 1.0f);
}

TEST_CASE("hybrid: levels 0 is the standard map itself, word for word") {
  const shadow::DepthMap source = stepMap();
  const HybridMap map = buildHybrid(source, windowRule(0.25f), 0);
  CHECK(map.rootSize == 4);
  CHECK(map.records.empty());
  for (int i = 0; i < 16; ++i) CHECK(map.root[std::size_t(i)] == leafWord(source.depth[std::size_t(i)]));
  CHECK(storedBytes(map, 0) == 64u);
  CHECK(descend(map, 3, 3).steps == 0);
}

TEST_CASE("hybrid: a size that does not halve evenly keeps its border blocks") {
  // 5x5, all 0.5: level 1 is 3x3; its last row and column are blocks cut by the border, so they
  // keep their children, the missing ones stored as the far plane (1.0, lit).
  const HybridMap map = buildHybrid(shadow::DepthMap(5, 5, 0.5f), windowRule(0.25f), 1);
  CHECK(map.rootSize == 3);
  CHECK(map.records.size() == 5u);  // (2, 0), (2, 1), (0, 2), (1, 2), (2, 2)
  CHECK(leafDepth(map.rootWord(0, 0)) == 0.5f);
  REQUIRE(isPointer(map.rootWord(2, 2)));
  const auto& corner = map.records[recordIndex(map.rootWord(2, 2))];
  CHECK(corner == std::array<std::uint32_t, 4>{leafWord(0.5f), leafWord(1.0f), leafWord(1.0f), leafWord(1.0f)});
  CHECK(descend(map, 4, 4).depth == 0.5f);
  CHECK(descend(map, 4, 4).level == 0);
  CHECK(descend(map, 9, -3).depth == 0.5f);  // clamped into the map
}

TEST_CASE("hybrid: bad input is refused with the value named") {
  CHECK_THROWS_WITH_AS(mergeSweep(stepMap(), windowRule(0.25f), 4), doctest::Contains("levels = 4 is not in 0..3"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(mergeSweep(shadow::DepthMap(4, 2, 0.5f), windowRule(0.25f), 1),
                       doctest::Contains("4x2, not square"), std::invalid_argument);
  HybridMap broken = buildHybrid(stepMap(), windowRule(0.01f), 2);
  broken.root[0] = kPointer | 7u;
  CHECK_THROWS_WITH_AS(descend(broken, 0, 0), doctest::Contains("record 7 of 2"), std::runtime_error);
}

namespace {

// An independent build of the same map: top-down recursion over the quadtree from its single top
// texel (through the levels above the root, which only group), records appended in depth-first
// order as it goes. Shares nothing with buildHybrid but the merge grids.
struct TopDown {
  const std::vector<MergeGrid>& grids;
  std::vector<std::array<std::uint32_t, 4>> records;
  std::vector<std::uint32_t> root;
  // Level k > levels groups; at the root level each texel's word is written where it belongs.
  void visit(int k, int x, int y, const std::vector<int>& sizes) {
    const int levels = int(grids.size()) - 1;
    if (x >= sizes[std::size_t(k)] || y >= sizes[std::size_t(k)]) return;
    if (k == levels) {
      root[std::size_t(y) * std::size_t(sizes[std::size_t(k)]) + std::size_t(x)] = word(k, x, y);
      return;
    }
    for (int i = 0; i < 4; ++i) visit(k - 1, 2 * x + (i & 1), 2 * y + (i >> 1), sizes);
  }
  std::uint32_t word(int k, int x, int y) {
    const MergeGrid& g = grids[std::size_t(k)];
    if (x >= g.size || y >= g.size) return leafWord(1.0f);
    if (k == 0 || g.at(x, y) >= 0.0f) return leafWord(g.at(x, y));
    const std::size_t index = records.size();
    records.emplace_back();
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t w = word(k - 1, 2 * x + (i & 1), 2 * y + (i >> 1));
      records[index][std::size_t(i)] = w;
    }
    return kPointer | std::uint32_t(index);
  }
};

// A random map with flat plateaus, slopes and steps, so every level has merged and kept texels.
shadow::DepthMap randomMap(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> d(std::size_t(n) * std::size_t(n));
  const float cx = u(rng) * float(n), cy = u(rng) * float(n), r = (0.2f + 0.3f * u(rng)) * float(n);
  const float slope = 0.2f * u(rng) / float(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const bool tower = (float(x) - cx) * (float(x) - cx) + (float(y) - cy) * (float(y) - cy) < r * r;
      float v = tower ? 0.4f : 0.8f + slope * float(x);
      if (u(rng) < 0.01f) v = 0.1f + 0.8f * u(rng);  // a few thin casters
      d[std::size_t(y) * std::size_t(n) + std::size_t(x)] = v;
    }
  return shadow::DepthMap(n, n, std::move(d));
}

}  // namespace

TEST_CASE("hybrid: random maps: the index matches a top-down build and every lookup the sweep") {
  std::mt19937_64 rng(test::seedFor("hybrid.random"));
  for (int trial = 0; trial < 12; ++trial) {
    const int n = trial % 3 == 0 ? 37 : 64;  // an odd size too
    const int levels = 1 + trial % 3;
    const shadow::DepthMap source = randomMap(rng, n);
    MergeRule rule = windowRule(0.02f);
    const std::vector<MergeGrid> grids = mergeSweep(source, rule, levels);
    const HybridMap map = buildHybrid(grids);
    INFO("seed ", test::seed(), " trial ", trial, " n ", n, " levels ", levels);

    std::vector<int> sizes{n};
    while (sizes.back() > 1 || int(sizes.size()) <= levels) sizes.push_back((sizes.back() + 1) / 2);
    TopDown reference{grids, {}, std::vector<std::uint32_t>(std::size_t(map.rootSize) * std::size_t(map.rootSize))};
    reference.visit(int(sizes.size()) - 1, 0, 0, sizes);
    CHECK(map.root == reference.root);
    CHECK(map.records == reference.records);

    // Every source texel finds the coarsest merged texel above it, or its own depth.
    std::uint64_t resolved = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int k = levels;
        while (k > 0 && !(grids[std::size_t(k)].at(x >> k, y >> k) >= 0.0f)) --k;
        const Descent d = descend(map, x, y);
        CHECK(d.level == k);
        CHECK(d.steps == levels - k);
        CHECK(d.depth == grids[std::size_t(k)].at(x >> k, y >> k));
        resolved += d.level == 0;
      }
    CHECK(resolved > 0u);
    const HybridCounts c = countHybrid(map);
    CHECK(c.sourceTexelsAt[0] >= resolved);
    CHECK(c.storedTexels == c.rootWords + 3 * c.records);  // each record turns one word into four
  }
}

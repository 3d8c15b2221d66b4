// Graders for lesson 07 (ctest -L ex07). Expected values are worked out by hand in the comments;
// the randomised cases compare against the rules written out independently here.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

// The paper's rule, written out again: mean in the stated order, every |m - Dn| <= eps0 Dn, never
// over a negative child.
bool rule(const std::array<float, 4>& d, float eps0, float* mean) {
  *mean = ((d[0] + d[1]) + (d[2] + d[3])) * 0.25f;
  for (float dn : d)
    if (dn < 0.0f || std::fabs(*mean - dn) > eps0 * dn) return false;
  return true;
}

hybrid::MergeGrid grid(int size, std::vector<float> values) { return {size, std::move(values)}; }

// The 4x4 map of the lesson's README: flat at 0.5 but one 2x2 block holding a step.
hybrid::MergeGrid stepMap() {
  return grid(4, {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.9f, 0.9f, 0.5f, 0.5f, 0.9f, 0.1f});
}

// Its hybrid map with eps0 = 0.01 and two levels, by hand: the root texel did not merge (record
// 0); of its four level-1 children three merged at 0.5 and (1, 1) did not (record 1), whose four
// level-0 children are 0.9, 0.9, 0.9, 0.1.
hybrid::HybridMap stepHybrid() {
  hybrid::HybridMap m;
  m.sourceSize = 4;
  m.levels = 2;
  m.rootSize = 1;
  m.root = {hybrid::kPointer | 0u};
  m.records = {{hybrid::leafWord(0.5f), hybrid::leafWord(0.5f), hybrid::leafWord(0.5f), hybrid::kPointer | 1u},
               {hybrid::leafWord(0.9f), hybrid::leafWord(0.9f), hybrid::leafWord(0.9f), hybrid::leafWord(0.1f)}};
  return m;
}

}  // namespace

TEST_CASE("ex07.1: the merge criterion by hand") {
  hybrid::BlockMerge b = ex07::mergeBlock({0.5f, 0.5f, 0.5f, 0.5f}, 0.0f);  // all equal: merged even at eps0 = 0
  CHECK(b.merged);
  CHECK(b.mean == 0.5f);
  // A tower top at 0.6 beside the ground at 0.75: m = 0.675; |m - 0.6| = 0.075 <= 0.25 * 0.6 = 0.15
  // and |m - 0.75| = 0.075 <= 0.1875: the paper's eps0 merges this silhouette.
  b = ex07::mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, 0.25f);
  CHECK(b.merged);
  CHECK(b.mean == doctest::Approx(0.675f));
  CHECK_FALSE(ex07::mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, 0.1f).merged);             // 0.075 > 0.06
  CHECK_FALSE(ex07::mergeBlock({0.1f, 0.9f, 0.9f, 0.9f}, 0.25f).merged);              // m = 0.7: |0.7 - 0.1| > 0.025
  CHECK_FALSE(ex07::mergeBlock({0.5f, 0.5f, hybrid::kInternal, 0.5f}, 1.0f).merged);  // a kept child
  // eps0 = 0.1 on 0.8, 0.8, 0.8, 1.0: m = 0.85, |0.85 - 0.8| = 0.05 <= 0.08, |0.85 - 1| = 0.15 > 0.1.
  CHECK_FALSE(ex07::mergeBlock({0.8f, 0.8f, 0.8f, 1.0f}, 0.1f).merged);
  CHECK(ex07::mergeBlock({0.8f, 0.8f, 0.8f, 1.0f}, 0.2f).merged);  // 0.15 <= 0.2
}

TEST_CASE("ex07.1: random blocks follow the rule") {
  std::mt19937_64 rng(test::seedFor("ex07.1"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int merged = 0;
  for (int i = 0; i < 500; ++i) {
    const float base = 0.05f + 0.9f * u(rng);
    std::array<float, 4> d;
    for (float& v : d) v = base + 0.1f * (u(rng) - 0.5f) * (i % 3 == 0 ? 4.0f : 1.0f);
    if (i % 17 == 0) d[std::size_t(i % 4)] = hybrid::kInternal;
    const float eps0 = 0.2f * u(rng);
    float mean = 0;
    const bool expected = rule(d, eps0, &mean);
    const hybrid::BlockMerge b = ex07::mergeBlock(d, eps0);
    INFO("seed ", test::seed(), " case ", i);
    CHECK(b.merged == expected);
    if (expected) CHECK(b.mean == mean);
    merged += expected;
  }
  CHECK(merged > 50);  // the sample holds both kinds
}

TEST_CASE("ex07.2: one level of the sweep by hand") {
  // eps0 = 0.01: three flat blocks merge at 0.5; the block with the step is kept.
  const hybrid::MergeGrid level1 = ex07::sweepLevel(stepMap(), 0.01f);
  CHECK(level1.size == 2);
  CHECK(level1.value == std::vector<float>{0.5f, 0.5f, 0.5f, hybrid::kInternal});
  // The next level: one of its children was kept, so it is kept.
  const hybrid::MergeGrid level2 = ex07::sweepLevel(level1, 0.01f);
  CHECK(level2.size == 1);
  CHECK(level2.value == std::vector<float>{hybrid::kInternal});
  // 3x3 of 0.25: (3 + 1) / 2 = 2 a side; only the block at (0, 0) lies whole inside.
  const hybrid::MergeGrid odd = ex07::sweepLevel(grid(3, std::vector<float>(9, 0.25f)), 0.5f);
  CHECK(odd.size == 2);
  CHECK(odd.value == std::vector<float>{0.25f, hybrid::kInternal, hybrid::kInternal, hybrid::kInternal});
}

TEST_CASE("ex07.2: random grids follow the block rule, block by block") {
  std::mt19937_64 rng(test::seedFor("ex07.2"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 2 + int(u(rng) * 30.0f);
    std::vector<float> v(std::size_t(n) * std::size_t(n));
    for (float& x : v) x = u(rng) < 0.1f ? hybrid::kInternal : 0.6f + 0.05f * u(rng);
    const float eps0 = 0.05f * u(rng);
    const hybrid::MergeGrid out = ex07::sweepLevel(grid(n, v), eps0);
    INFO("seed ", test::seed(), " trial ", trial, " size ", n);
    REQUIRE(out.size == (n + 1) / 2);
    REQUIRE(out.value.size() == std::size_t(out.size) * std::size_t(out.size));
    for (int y = 0; y < out.size; ++y)
      for (int x = 0; x < out.size; ++x) {
        float expected = hybrid::kInternal, mean = 0;
        auto at = [&](int cx, int cy) { return v[std::size_t(cy) * std::size_t(n) + std::size_t(cx)]; };
        if (2 * x + 1 < n && 2 * y + 1 < n &&
            rule({at(2 * x, 2 * y), at(2 * x + 1, 2 * y), at(2 * x, 2 * y + 1), at(2 * x + 1, 2 * y + 1)}, eps0, &mean))
          expected = mean;
        CHECK(out.value[std::size_t(y) * std::size_t(out.size) + std::size_t(x)] == expected);
      }
  }
}

TEST_CASE("ex07.3: the index descent by hand") {
  const hybrid::HybridMap map = stepHybrid();
  // (3, 3): root -> record 0, child (1, 1) -> record 1, child (1, 1): 0.1 at level 0, two steps.
  hybrid::Descent d = ex07::descend(map, 3, 3);
  CHECK(d.depth == 0.1f);
  CHECK(d.level == 0);
  CHECK(d.steps == 2);
  // (2, 3): the same record 1, child (0, 1): 0.9.
  d = ex07::descend(map, 2, 3);
  CHECK(d.depth == 0.9f);
  CHECK(d.level == 0);
  // (1, 2): record 0, child (0, 1): merged at 0.5, level 1, one step.
  d = ex07::descend(map, 1, 2);
  CHECK(d.depth == 0.5f);
  CHECK(d.level == 1);
  CHECK(d.steps == 1);
  // A map whose root texel merged: no step at all.
  hybrid::HybridMap flat = map;
  flat.root = {hybrid::leafWord(0.3f)};
  d = ex07::descend(flat, 2, 1);
  CHECK(d.depth == 0.3f);
  CHECK(d.level == 2);
  CHECK(d.steps == 0);
}

TEST_CASE("ex07.3: random maps: every texel finds the coarsest merged texel above it") {
  std::mt19937_64 rng(test::seedFor("ex07.3"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 16 + 8 * (trial % 4), levels = 1 + trial % 3;
    std::vector<float> d(std::size_t(n) * std::size_t(n));
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        d[std::size_t(y) * n + x] = (x / 5 + y / 7) % 3 == 0 ? 0.4f : 0.8f + 0.3f * u(rng) * (u(rng) < 0.05f);
    hybrid::MergeRule r;
    r.eps0 = 0.01f;
    const auto grids = hybrid::mergeSweep(shadow::DepthMap(n, n, d), r, levels);
    const hybrid::HybridMap map = hybrid::buildHybrid(grids);
    INFO("seed ", test::seed(), " trial ", trial);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int k = levels;  // the coarsest level that merged above (x, y), by the grids themselves
        while (k > 0 && grids[std::size_t(k)].at(x >> k, y >> k) < 0.0f) --k;
        const hybrid::Descent got = ex07::descend(map, x, y);
        CHECK(got.level == k);
        CHECK(got.steps == levels - k);
        CHECK(got.depth == grids[std::size_t(k)].at(x >> k, y >> k));
      }
  }
}

TEST_CASE("ex07.4: linear depth by hand") {
  // n = 1, f = 100: d = 0 is the near plane, d = 1 the far one.
  CHECK(ex07::linearDepth(0.0f, 1.0f, 100.0f) == doctest::Approx(1.0f));
  CHECK(ex07::linearDepth(1.0f, 1.0f, 100.0f) == doctest::Approx(100.0f));
  // d = 0.5: 2 * 100 / (101 - 0) = 1.980198: half the window depth is two metres from the light.
  CHECK(ex07::linearDepth(0.5f, 1.0f, 100.0f) == doctest::Approx(1.980198f));
  // d = 10/11 * ... : z = 10 gives 2d - 1 = (101 - 20) / 99, d = 0.9090909.
  CHECK(ex07::linearDepth(0.9090909f, 1.0f, 100.0f) == doctest::Approx(10.0f).epsilon(1e-4));
}

TEST_CASE("ex07.4: random distances come back from their window depth") {
  std::mt19937_64 rng(test::seedFor("ex07.4"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double n = 0.1 + 5.0 * u(rng), f = n + 10.0 + 300.0 * u(rng), z = n + (f - n) * u(rng);
    // The perspective's window depth of eye distance z, in double.
    const double d = 0.5 * (((f + n) - 2.0 * n * f / z) / (f - n)) + 0.5;
    INFO("seed ", test::seed(), " n ", n, " f ", f, " z ", z);
    CHECK(ex07::linearDepth(float(d), float(n), float(f)) == doctest::Approx(z).epsilon(2e-3));
  }
}

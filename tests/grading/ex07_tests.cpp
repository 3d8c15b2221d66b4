// Graders for lesson 07 (make grade LESSON=07): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases compare with the reference implementation (compiled into
// the course library). More cases, with seeds the grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "algorithms/hybrid_map.hpp"
#include "ex07_maps.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::kApprox;

namespace {

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

// A merge grid as expected: its size, then texel by texel (the first wrong texel is reported;
// kInternal = -1 where a texel did not merge).
bool sameGrid(const hybrid::MergeGrid& got, const hybrid::MergeGrid& expected) {
  if (!CHECK_EXACT(got.size, expected.size)) return false;
  if (!CHECK_EXACT(int(got.value.size()), expected.size * expected.size)) return false;
  for (int y = 0; y < expected.size; ++y)
    for (int x = 0; x < expected.size; ++x) {
      INFO("texel (", x, ", ", y, ") of the ", expected.size, " x ", expected.size, " result");
      if (!CHECK_EXACT(got.at(x, y), expected.at(x, y))) return false;
    }
  return true;
}

bool sameDescent(const hybrid::Descent& got, const hybrid::Descent& expected) {
  return CHECK_EXACT(got.depth, expected.depth) && CHECK_EXACT(got.level, expected.level) &&
         CHECK_EXACT(got.steps, expected.steps);
}

}  // namespace

TEST_CASE("ex07.1: the merge criterion by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  hybrid::BlockMerge b = ex07::mergeBlock({0.5f, 0.5f, 0.5f, 0.5f}, 0.0f);  // all equal: merged even at eps0 = 0
  CHECK_EXACT(b.merged, true);
  CHECK_EXACT(b.mean, 0.5f);
  // A tower top at 0.6 beside the ground at 0.75: m = 0.675; |m - 0.6| = 0.075 <= 0.25 * 0.6 = 0.15
  // and |m - 0.75| = 0.075 <= 0.1875: the paper's eps0 merges this silhouette.
  b = ex07::mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, 0.25f);
  CHECK_EXACT(b.merged, true);
  CHECK_NEAR(b.mean, 0.675f, kApprox);
  CHECK_EXACT(ex07::mergeBlock({0.6f, 0.6f, 0.75f, 0.75f}, 0.1f).merged, false);  // 0.075 > 0.06
  CHECK_EXACT(ex07::mergeBlock({0.1f, 0.9f, 0.9f, 0.9f}, 0.25f).merged, false);   // m = 0.7: |0.7 - 0.1| > 0.025
  CHECK_EXACT(ex07::mergeBlock({0.5f, 0.5f, hybrid::kInternal, 0.5f}, 1.0f).merged, false);  // a kept child
  // eps0 = 0.1 on 0.8, 0.8, 0.8, 1.0: m = 0.85, |0.85 - 0.8| = 0.05 <= 0.08, |0.85 - 1| = 0.15 > 0.1.
  CHECK_EXACT(ex07::mergeBlock({0.8f, 0.8f, 0.8f, 1.0f}, 0.1f).merged, false);
  CHECK_EXACT(ex07::mergeBlock({0.8f, 0.8f, 0.8f, 1.0f}, 0.2f).merged, true);  // 0.15 <= 0.2
}

TEST_CASE("ex07.1: random blocks against the reference") {
  std::mt19937_64 rng(test::seedFor("ex07.1"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 500; ++i) {
    const float base = 0.05f + 0.9f * u(rng);
    std::array<float, 4> d;
    for (float& v : d) v = base + 0.1f * (u(rng) - 0.5f) * (i % 3 == 0 ? 4.0f : 1.0f);
    if (i % 17 == 0) d[std::size_t(i % 4)] = hybrid::kInternal;
    const float eps0 = 0.2f * u(rng);
    const hybrid::BlockMerge expected = hybrid::mergeBlock(d, hybrid::MergeRule{hybrid::Criterion::Window, eps0}, 1);
    const hybrid::BlockMerge b = ex07::mergeBlock(d, eps0);
    INFO("random case ", i, " of 500 (seed ", test::seed(), "): depths ", d[0], " ", d[1], " ", d[2], " ", d[3],
         ", eps0 ", eps0);
    if (!CHECK_EXACT(b.merged, expected.merged)) break;
    if (expected.merged && !CHECK_EXACT(b.mean, expected.mean)) break;
  }
}

TEST_CASE("ex07.2: one level of the sweep by hand") {
  {
    // eps0 = 0.01: three flat blocks merge at 0.5; the block with the step is kept. The next
    // level: one of its children was kept, so it is kept.
    INFO("the README's 4 x 4 map, eps0 = 0.01, then its level 1");
    const hybrid::MergeGrid level1 = ex07::sweepLevel(stepMap(), 0.01f);
    if (sameGrid(level1, grid(2, {0.5f, 0.5f, 0.5f, hybrid::kInternal})))
      sameGrid(ex07::sweepLevel(level1, 0.01f), grid(1, {hybrid::kInternal}));
  }
  {
    // 3x3 of 0.25: (3 + 1) / 2 = 2 a side; only the block at (0, 0) lies whole inside.
    INFO("a 3 x 3 map of 0.25, eps0 = 0.5");
    sameGrid(ex07::sweepLevel(grid(3, std::vector<float>(9, 0.25f)), 0.5f),
             grid(2, {0.25f, hybrid::kInternal, hybrid::kInternal, hybrid::kInternal}));
  }
}

TEST_CASE("ex07.2: random grids against the reference") {
  std::mt19937_64 rng(test::seedFor("ex07.2"));
  for (int trial = 0; trial < 20; ++trial) {
    const test::RandomLevel l = test::randomLevel(rng);
    const int n = l.children.size;
    INFO("random grid ", trial, " of 20 (seed ", test::seed(), "): ", n, " x ", n, ", eps0 ", l.eps0);
    const hybrid::MergeGrid expected =
        hybrid::sweepLevel(l.children, hybrid::MergeRule{hybrid::Criterion::Window, l.eps0}, 1);
    if (!sameGrid(ex07::sweepLevel(l.children, l.eps0), expected)) break;
  }
}

TEST_CASE("ex07.3: the index descent by hand") {
  const hybrid::HybridMap map = stepHybrid();
  {
    INFO("the README's 4 x 4 map as a hybrid map of two levels (eps0 = 0.01), source texel (3, 3)");
    // Root -> record 0, child (1, 1) -> record 1, child (1, 1): 0.1 at level 0, two steps.
    sameDescent(ex07::descend(map, 3, 3), {0.1f, 0, 2});
  }
  {
    INFO("the same map, source texel (2, 3)");  // the same record 1, child (0, 1): 0.9
    sameDescent(ex07::descend(map, 2, 3), {0.9f, 0, 2});
  }
  {
    INFO("the same map, source texel (1, 2)");  // record 0, child (0, 1): merged at 0.5, level 1, one step
    sameDescent(ex07::descend(map, 1, 2), {0.5f, 1, 1});
  }
  {
    // A map whose root texel merged: no step at all.
    hybrid::HybridMap flat = map;
    flat.root = {hybrid::leafWord(0.3f)};
    INFO("the same map with a merged root texel of 0.3, source texel (2, 1)");
    sameDescent(ex07::descend(flat, 2, 1), {0.3f, 2, 0});
  }
}

TEST_CASE("ex07.3: random maps against the reference") {
  std::mt19937_64 rng(test::seedFor("ex07.3"));
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 16 + 8 * (trial % 4), levels = 1 + trial % 3;
    const hybrid::HybridMap map = hybrid::buildHybrid(test::randomSweep(rng, n, levels, {3, 5, 4}, 0.3f, 0.7f));
    bool ok = true;
    for (int y = 0; y < n && ok; ++y)
      for (int x = 0; x < n && ok; ++x) {
        INFO("random map ", trial, " of 10 (seed ", test::seed(), "): ", n, " x ", n, ", ", levels,
             " levels, source texel (", x, ", ", y, ")");
        ok = sameDescent(ex07::descend(map, x, y), hybrid::descend(map, x, y));
      }
    if (!ok) break;
  }
}

TEST_CASE("ex07.4: linear depth by hand" * SHADOWLAB_INDEPENDENT_CHECKS) {
  // n = 1, f = 100: d = 0 is the near plane, d = 1 the far one.
  CHECK_NEAR(ex07::linearDepth(0.0f, 1.0f, 100.0f), 1.0f, kApprox);
  CHECK_NEAR(ex07::linearDepth(1.0f, 1.0f, 100.0f), 100.0f, kApprox);
  // d = 0.5: 2 * 100 / (101 - 0) = 1.980198: half the window depth is two metres from the light.
  CHECK_NEAR(ex07::linearDepth(0.5f, 1.0f, 100.0f), 1.980198f, kApprox);
  // d = 10/11 * ... : z = 10 gives 2d - 1 = (101 - 20) / 99, d = 0.9090909.
  CHECK_NEAR(ex07::linearDepth(0.9090909f, 1.0f, 100.0f), 10.0f, grading::relativeTolerance(1e-4));
}

TEST_CASE("ex07.4: random window depths against the reference") {
  std::mt19937_64 rng(test::seedFor("ex07.4"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const float n = 0.1f + 5.0f * u(rng), f = n + 10.0f + 300.0f * u(rng), d = u(rng);
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): window depth ", d, ", near ", n, ", far ", f);
    if (!CHECK_NEAR(ex07::linearDepth(d, n, f), hybrid::linearDepth(d, {true, n, f, 0.0f}), kApprox)) break;
  }
}

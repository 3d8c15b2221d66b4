// Hidden cases for lesson 07 (instructor tree only): the rules written out independently of the
// reference, with the seed the grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "../ex07_maps.hpp"
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
}  // namespace

TEST_SUITE("hidden") {
  TEST_CASE("ex07.1: random blocks follow the rule") {
    std::mt19937_64 rng(test::seedFor("ex07.1 hidden"));
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int merged = 0, i = 0;
    for (; i < 500; ++i) {
      const float base = 0.05f + 0.9f * u(rng);
      std::array<float, 4> d;
      for (float& v : d) v = base + 0.1f * (u(rng) - 0.5f) * (i % 3 == 0 ? 4.0f : 1.0f);
      if (i % 13 == 0) d[std::size_t(i % 4)] = hybrid::kInternal;
      const float eps0 = 0.2f * u(rng);
      float mean = 0;
      const bool expected = rule(d, eps0, &mean);
      const hybrid::BlockMerge b = ex07::mergeBlock(d, eps0);
      INFO("random case ", i, " of 500 (seed ", test::seed(), "): depths ", d[0], " ", d[1], " ", d[2], " ", d[3],
           ", eps0 ", eps0);
      if (!CHECK_EXACT(b.merged, expected)) break;
      if (expected && !CHECK_EXACT(b.mean, mean)) break;
      merged += expected;
    }
    INFO("the sample holds both kinds: ", merged, " of 500 blocks merge by the rule");
    if (i == 500) CHECK_TRUE(merged > 50);
  }

  TEST_CASE("ex07.2: random grids follow the block rule, block by block") {
    std::mt19937_64 rng(test::seedFor("ex07.2 hidden"));
    for (int trial = 0; trial < 20; ++trial) {
      const test::RandomLevel l = test::randomLevel(rng);
      const int n = l.children.size;
      const float eps0 = l.eps0;
      const std::vector<float>& v = l.children.value;
      const hybrid::MergeGrid out = ex07::sweepLevel(l.children, eps0);
      INFO("random grid ", trial, " of 20 (seed ", test::seed(), "): ", n, " x ", n, ", eps0 ", eps0);
      if (!CHECK_EXACT(out.size, (n + 1) / 2)) break;
      if (!CHECK_EXACT(int(out.value.size()), out.size * out.size)) break;
      bool ok = true;
      auto at = [&](int cx, int cy) { return v[std::size_t(cy) * std::size_t(n) + std::size_t(cx)]; };
      for (int y = 0; y < out.size && ok; ++y)
        for (int x = 0; x < out.size && ok; ++x) {
          float expected = hybrid::kInternal, mean = 0;
          if (2 * x + 1 < n && 2 * y + 1 < n &&
              rule({at(2 * x, 2 * y), at(2 * x + 1, 2 * y), at(2 * x, 2 * y + 1), at(2 * x + 1, 2 * y + 1)}, eps0,
                   &mean))
            expected = mean;
          INFO("texel (", x, ", ", y, ")");
          ok = CHECK_EXACT(out.at(x, y), expected);
        }
      if (!ok) break;
    }
  }

  TEST_CASE("ex07.3: random maps: every texel finds the coarsest merged texel above it") {
    std::mt19937_64 rng(test::seedFor("ex07.3 hidden"));
    for (int trial = 0; trial < 10; ++trial) {
      const int n = 16 + 8 * (trial % 4), levels = 1 + trial % 3;
      const auto grids = test::randomSweep(rng, n, levels, {5, 7, 3}, 0.4f, 0.8f);
      const hybrid::HybridMap map = hybrid::buildHybrid(grids);
      bool ok = true;
      for (int y = 0; y < n && ok; ++y)
        for (int x = 0; x < n && ok; ++x) {
          int k = levels;  // the coarsest level that merged above (x, y), by the grids themselves
          while (k > 0 && grids[std::size_t(k)].at(x >> k, y >> k) < 0.0f) --k;
          const hybrid::Descent got = ex07::descend(map, x, y);
          INFO("random map ", trial, " of 10 (seed ", test::seed(), "): ", n, " x ", n, ", ", levels,
               " levels, source texel (", x, ", ", y, ")");
          ok = CHECK_EXACT(got.level, k) && CHECK_EXACT(got.steps, levels - k) &&
               CHECK_EXACT(got.depth, grids[std::size_t(k)].at(x >> k, y >> k));
        }
      if (!ok) break;
    }
  }

  TEST_CASE("ex07.4: random distances come back from their window depth") {
    std::mt19937_64 rng(test::seedFor("ex07.4 hidden"));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const double n = 0.1 + 5.0 * u(rng), f = n + 10.0 + 300.0 * u(rng), z = n + (f - n) * u(rng);
      // The perspective's window depth of eye distance z, in double.
      const double d = 0.5 * (((f + n) - 2.0 * n * f / z) / (f - n)) + 0.5;
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): near ", n, ", far ", f, ", distance ", z,
           ", window depth ", d);
      if (!CHECK_NEAR(ex07::linearDepth(float(d), float(n), float(f)), z, grading::relativeTolerance(2e-3))) break;
    }
  }
}

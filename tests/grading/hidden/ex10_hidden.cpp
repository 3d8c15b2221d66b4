// Hidden cases for lesson 10 (instructor tree only): each statement's formula written another way
// (the split as zNear times a blend of growth factors; the snap through the grid's integers; the
// cascade by scanning from the far end), with the seed the grader chooses.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

TEST_SUITE("hidden") {
  TEST_CASE("ex10.1: random ranges: zNear times a blend of the growth factors, lambda's order kept") {
    std::mt19937_64 rng(test::seedFor("ex10.1 hidden"));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const double zn = 1e-3 + 5.0 * u(rng), ratio = 1.01 + 1000.0 * u(rng), zf = zn * ratio;
      const int n = 1 + int(rng() % 4);
      const double lambda = u(rng);
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): zNear ", zn, ", zFar ", zf, ", count ", n,
           ", lambda ", lambda);
      const std::vector<double> s = ex10::practicalSplits(zn, zf, n, lambda);
      if (!CHECK_EXACT(int(s.size()), n + 1)) break;
      if (!CHECK_EXACT(s.front() == zn && s.back() == zf, true)) break;
      // z_i / zNear = lambda ratio^t + (1 - lambda)(1 + (ratio - 1) t), t = i / n.
      bool ok = true;
      for (int k = 1; k < n && ok; ++k) {
        const double t = double(k) / double(n);
        const double want = zn * (lambda * std::pow(ratio, t) + (1.0 - lambda) * (1.0 + (ratio - 1.0) * t));
        INFO("z_", k);
        ok = CHECK_NEAR(s[std::size_t(k)], want, grading::relativeTolerance(1e-9));
      }
      if (!ok) break;
      // More lambda: nearer splits (the logarithmic one lies below the uniform one inside the range).
      const std::vector<double> more = ex10::practicalSplits(zn, zf, n, std::min(1.0, lambda + 0.25));
      for (int k = 1; k < n && ok; ++k) {
        INFO("z_", k, " with lambda raised by 0.25 must not lie farther out");
        ok = CHECK_TRUE(more.size() == s.size() && more[std::size_t(k)] <= s[std::size_t(k)] * (1.0 + 1e-12));
      }
      if (!ok) break;
    }
  }

  TEST_CASE("ex10.2: random boxes: h a whole number of quarter powers of two, the centre on whole texels") {
    std::mt19937_64 rng(test::seedFor("ex10.2 hidden"));
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 300; ++i) {
      const int size = 1 << (6 + int(rng() % 7));  // 64 .. 4096
      const glm::vec2 half(0.01f + 300.0f * u(rng) * u(rng), 0.01f + 300.0f * u(rng) * u(rng));
      const float reach = 3.0f * std::max(half.x, half.y);  // the centre within 3 boxes: exact in float
      const glm::vec2 centre(reach * (2.0f * u(rng) - 1.0f), reach * (2.0f * u(rng) - 1.0f));
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): centre ", grading::show(centre), ", half ",
           grading::show(half), ", ", size, " texels");
      const shadow::TexelSnap s = ex10::snapToTexels(centre, half, size);
      const float need = std::max(half.x, half.y) * (1.0f + 2.0f / float(size));
      // h in (need, need + step], step the quarter of the power of two at or above need.
      int e = 0;
      std::frexp(need, &e);  // need in [2^(e-1), 2^e)
      const float pow2 = need == std::ldexp(1.0f, e - 1) ? std::ldexp(1.0f, e - 1) : std::ldexp(1.0f, e);
      const float step = pow2 / 4.0f;
      INFO("the box needs ", need, "; its step is ", step);
      if (!CHECK_TRUE(s.half >= need * (1.0f - 1e-6f) && s.half <= need + step * (1.0f + 1e-5f))) break;
      const double quarters = double(s.half) / double(step);
      if (!CHECK_NEAR(quarters, std::round(quarters), 1e-4)) break;
      const double texel = 2.0 * double(s.half) / double(size);
      const glm::dvec2 k = glm::dvec2(s.centre) / texel;
      if (!CHECK_NEAR(k, glm::round(k), 2e-3)) break;
      const glm::dvec2 off = glm::abs(glm::dvec2(s.centre) - glm::dvec2(centre)) / texel;
      INFO("the centre moved by ", grading::show(off), " texels: at most half of one");
      if (!CHECK_TRUE(off.x <= 0.5 + 2e-3 && off.y <= 0.5 + 2e-3)) break;
    }
  }

  TEST_CASE("ex10.3: random splits: the cascade found from the far end, the weight linear in the band") {
    std::mt19937_64 rng(test::seedFor("ex10.3 hidden"));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
      const int n = 1 + int(rng() % 4);
      std::vector<double> s = {0.05 + 2.0 * u(rng)};
      for (int k = 0; k < n; ++k) s.push_back(s.back() * (1.2 + 3.0 * u(rng)));
      const double band = 0.05 + 0.45 * u(rng);
      // A depth inside cascade c at fraction f of its range, or just outside the whole range.
      const int c = int(rng() % std::uint64_t(n));
      const double f = u(rng), lo = s[std::size_t(c)], hi = s[std::size_t(c) + 1];
      const int where = int(rng() % 10);
      const double depth = where == 0   ? s.front() * (1.0 - 0.1 * u(rng) - 1e-9)
                           : where == 1 ? s.back() * (1.0 + 0.1 * u(rng) + 1e-9)
                                        : lo + (hi - lo) * std::max(f, 1e-9);
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): ", n, " cascades from ", s.front(), " to ", s.back(),
           ", band ", band, ", depth ", depth);
      const shadow::CascadeBlend b = ex10::cascadeAt(s, depth, band);
      int want = -1;
      for (int k = n - 1; k >= 0; --k)
        if (depth <= s[std::size_t(k) + 1] && depth >= s.front()) want = k;
      if (!CHECK_EXACT(b.cascade, want)) break;
      double weight = 0.0;
      if (want >= 0 && want < n - 1) {
        const double g = (depth - s[std::size_t(want)]) / (s[std::size_t(want) + 1] - s[std::size_t(want)]);
        weight = std::clamp((g - (1.0 - band)) / band, 0.0, 1.0);  // the fraction through the band
      }
      if (!CHECK_NEAR(b.nextWeight, weight, 1e-6)) break;
    }
  }
}

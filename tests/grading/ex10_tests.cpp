// Grader for lesson 10 (make grade LESSON=10): the public cases. Hand-computed cases first (worked out in
// the comments), then seeded random ones that check the statement's formulas and properties. More
// cases, with seeds the grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::kApprox;
using grading::relativeTolerance;

namespace {

// The statement of 10.1, term by term, so a failure can say which half of the blend is off.
double logSplit(double zn, double zf, int i, int n) { return zn * std::pow(zf / zn, double(i) / n); }
double uniformSplit(double zn, double zf, int i, int n) { return zn + (zf - zn) * double(i) / n; }

// Checks one answer of 10.1 against the formula; false at the first wrong distance.
bool checkSplits(const std::vector<double>& s, double zn, double zf, int n, double lambda) {
  INFO("zNear ", zn, ", zFar ", zf, ", count ", n, ", lambda ", lambda);
  if (!CHECK_EXACT(int(s.size()), n + 1)) return false;  // count cascades have count + 1 ends
  {
    INFO("the two ends are exactly zNear and zFar (set them after the loop: pow rounds)");
    if (!CHECK_EXACT(s.front() == zn && s.back() == zf, true)) return false;
  }
  for (int i = 1; i < n; ++i) {
    const double lg = logSplit(zn, zf, i, n), un = uniformSplit(zn, zf, i, n);
    INFO("z_", i, ": the logarithmic split is ", lg, ", the uniform one ", un, "; lambda weighs the logarithmic one");
    if (!CHECK_NEAR(s[std::size_t(i)], lambda * lg + (1.0 - lambda) * un, relativeTolerance(1e-12))) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("ex10.1: the practical split scheme, by hand") {
  // zNear 1, zFar 16, four cascades. lambda 1 (logarithmic): each split doubles, 1 2 4 8 16.
  CHECK_TRUE(checkSplits(ex10::practicalSplits(1.0, 16.0, 4, 1.0), 1.0, 16.0, 4, 1.0));
  // lambda 0 (uniform): steps of 15 / 4 = 3.75: 1 4.75 8.5 12.25 16.
  // lambda 0.5: halfway, (2 + 4.75) / 2 = 3.375, (4 + 8.5) / 2 = 6.25, (8 + 12.25) / 2 = 10.125.
  const struct {
    double lambda;
    std::vector<double> want;
    const char* why;
  } byHand[] = {
      {0.0, {1.0, 4.75, 8.5, 12.25, 16.0}, "lambda = 0 is the uniform split: 1, 4.75, 8.5, 12.25, 16"},
      {0.5, {1.0, 3.375, 6.25, 10.125, 16.0}, "lambda = 0.5 is halfway between the two: 1, 3.375, 6.25, 10.125, 16"}};
  for (const auto& c : byHand) {
    const std::vector<double> s = ex10::practicalSplits(1.0, 16.0, 4, c.lambda);
    const std::string why = c.why;
    INFO(why);
    if (!CHECK_EXACT(int(s.size()), 5)) continue;
    for (std::size_t i = 1; i < 4; ++i) CHECK_NEAR(s[i], c.want[i], kApprox);
  }
  // One cascade: just the two ends.
  CHECK_TRUE(checkSplits(ex10::practicalSplits(0.5, 200.0, 1, 0.75), 0.5, 200.0, 1, 0.75));
}

TEST_CASE("ex10.1: random ranges, counts and lambdas: the blend, exact ends, increasing") {
  std::mt19937_64 rng(test::seedFor("ex10.1 random"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double zn = 0.01 + 2.0 * u(rng), zf = zn * (1.5 + 500.0 * u(rng)), lambda = u(rng);
    const int n = 1 + int(rng() % 4);
    INFO("random case ", i, " of 200 (seed ", test::seed(), ")");
    const std::vector<double> s = ex10::practicalSplits(zn, zf, n, lambda);
    if (!CHECK_TRUE(checkSplits(s, zn, zf, n, lambda))) break;
    bool increasing = true;
    for (std::size_t k = 1; k < s.size(); ++k) increasing = increasing && s[k] > s[k - 1];
    INFO("each cascade starts where the one before it ends, farther out");
    if (!CHECK_TRUE(increasing)) break;
  }
}

TEST_CASE("ex10.2: texel snapping, by hand") {
  // half (3, 1), 1024 texels: h = 3 (1 + 2/1024) = 3.005859375; log2 h = 1.59, so step = 2^2 / 4 = 1
  // and h = ceil(3.0059) = 4. texel = 8 / 1024 = 0.0078125; centre 0.3 / texel = 38.4 -> 38 ->
  // 0.296875; -0.2 / texel = -25.6 -> -26 -> -0.203125.
  {
    const shadow::TexelSnap a = ex10::snapToTexels({0.3f, -0.2f}, {3.0f, 1.0f}, 1024);
    INFO("centre (0.3, -0.2), half (3, 1), 1024 texels: h 3.0059 rounds up to its step 1, the texel is 8/1024");
    CHECK_NEAR(a.half, 4.0f, kApprox);
    CHECK_NEAR(a.centre, glm::vec2(0.296875f, -0.203125f), 1e-6);
  }
  // half (0.1, 0.7), 256 texels: h = 0.7 (1 + 2/256) = 0.70546875; log2 h = -0.50, step = 2^0 / 4 =
  // 0.25, h = 0.75. texel = 1.5 / 256 = 0.005859375; centre 10 / texel = 1706.67 -> 1707 -> 10.001953125.
  {
    const shadow::TexelSnap b = ex10::snapToTexels({10.0f, 0.0f}, {0.1f, 0.7f}, 256);
    INFO("centre (10, 0), half (0.1, 0.7), 256 texels: the larger half wins, h 0.7055 rounds up to 0.75");
    CHECK_NEAR(b.half, 0.75f, kApprox);
    CHECK_NEAR(b.centre, glm::vec2(10.001953125f, 0.0f), 1e-5);
  }
  // A degenerate box still gets a size: max(..., 1e-3).
  const shadow::TexelSnap c = ex10::snapToTexels({0.0f, 0.0f}, {0.0f, 0.0f}, 2048);
  INFO("a zero-sized box: h starts from 1e-3, so the map is never degenerate");
  CHECK_TRUE(c.half >= 1e-3f && c.half < 2e-3f);
}

TEST_CASE("ex10.2: a moving camera: the size holds still and the centre moves by whole texels") {
  std::mt19937_64 rng(test::seedFor("ex10.2 random"));
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int sizes[] = {512, 1024, 2048};
  for (int i = 0; i < 200; ++i) {
    const int size = sizes[rng() % 3];
    const glm::vec2 half(1.0f + 60.0f * u(rng), 1.0f + 60.0f * u(rng));
    // Within a few boxes of the light's origin: the centre in texels stays exact in float.
    const float reach = 4.0f * std::max(half.x, half.y);
    const glm::vec2 centre(reach * (2.0f * u(rng) - 1.0f), reach * (2.0f * u(rng) - 1.0f));
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): centre ", grading::show(centre), ", half ",
         grading::show(half), ", ", size, " texels");
    const shadow::TexelSnap s = ex10::snapToTexels(centre, half, size);
    const float h0 = std::max(half.x, half.y) * (1.0f + 2.0f / float(size));
    const float step = std::exp2(std::ceil(std::log2(h0))) / 4.0f;
    INFO("h = max(half) (1 + 2/size) = ", h0, " rounded UP to a multiple of its step ", step);
    if (!CHECK_NEAR(s.half, std::ceil(h0 / step) * step, relativeTolerance(1e-6))) break;
    const double texel = 2.0 * double(s.half) / double(size);
    const glm::dvec2 onGrid = glm::dvec2(s.centre) / texel;
    INFO("the centre in texels is ", grading::show(onGrid), ": it must be whole (round(centre / texel) * texel)");
    if (!CHECK_NEAR(onGrid, glm::round(onGrid), 1e-3)) break;
    INFO("the snapped box must still hold the fitted one: the centre moved at most half a texel");
    if (!CHECK_NEAR(s.centre, centre, 0.5005 * texel)) break;
    // The camera moves a little: the same step, so the same h and a centre on the same grid.
    const glm::vec2 moved = centre + glm::vec2(0.37f, -0.21f) * float(texel);
    const shadow::TexelSnap m = ex10::snapToTexels(moved, half, size);
    INFO("after a move of a third of a texel the size must not change (else the edges crawl)");
    if (!CHECK_NEAR(m.half, s.half, relativeTolerance(1e-6))) break;
  }
}

TEST_CASE("ex10.3: the cascade for a view depth and the blend band, by hand") {
  // Splits 1 2 4 8 (three cascades), band 0.25. Cascade 0 blends on [1.75, 2], cascade 1 on [3.5, 4].
  const std::vector<double> s = {1.0, 2.0, 4.0, 8.0};
  auto check = [&](double depth, int cascade, double weight) {
    const shadow::CascadeBlend b = ex10::cascadeAt(s, depth, 0.25);
    INFO("splits 1 2 4 8, band 0.25, depth ", depth, ": want cascade ", cascade, " with next weight ", weight, ", got ",
         b.cascade, " with ", b.nextWeight);
    return CHECK_EXACT(b.cascade, cascade) && CHECK_NEAR(b.nextWeight, weight, kApprox);
  };
  check(1.0, 0, 0.0);    // the near plane is in cascade 0
  check(1.5, 0, 0.0);    // before the band
  check(1.875, 0, 0.5);  // halfway through cascade 0's band [1.75, 2]
  check(2.0, 0, 1.0);    // exactly on the split: the nearer cascade, fully blended
  check(3.0, 1, 0.0);
  check(3.75, 1, 0.5);  // cascade 1's band is a quarter of ITS range: [3.5, 4]
  check(7.9, 2, 0.0);   // the last cascade has nobody to blend into
  check(8.0, 2, 0.0);
  check(0.5, -1, 0.0);  // nearer than the near plane: no map covers it
  check(8.5, -1, 0.0);  // beyond the last split
  const shadow::CascadeBlend hard = ex10::cascadeAt(s, 1.99, 0.0);
  INFO("band 0 is a hard switch: depth 1.99 is cascade 0 with weight 0");
  CHECK_EXACT(hard.cascade, 0);
  CHECK_NEAR(hard.nextWeight, 0.0, kApprox);
}

TEST_CASE("ex10.3: random splits and depths: the right slice, a weight rising 0 to 1 across the band") {
  std::mt19937_64 rng(test::seedFor("ex10.3 random"));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    const int n = 1 + int(rng() % 4);
    std::vector<double> s = {0.1 + u(rng)};
    for (int k = 0; k < n; ++k) s.push_back(s.back() + 0.5 + 20.0 * u(rng));
    const double band = 0.5 * u(rng), depth = s.front() + (s.back() - s.front()) * u(rng);
    INFO("random case ", i, " of 300 (seed ", test::seed(), "): ", n, " cascades from ", s.front(), " to ", s.back(),
         ", band ", band, ", depth ", depth);
    const shadow::CascadeBlend b = ex10::cascadeAt(s, depth, band);
    int want = 0;
    while (want < n - 1 && depth > s[std::size_t(want) + 1]) ++want;
    INFO("the depth lies in [", s[std::size_t(want)], ", ", s[std::size_t(want) + 1], "]");
    if (!CHECK_EXACT(b.cascade, want)) break;
    double weight = 0.0, width = 0.0, start = s.back();
    if (want < n - 1) {  // the last cascade blends into nothing
      width = band * (s[std::size_t(want) + 1] - s[std::size_t(want)]);
      start = s[std::size_t(want) + 1] - width;
      weight = depth > start ? std::min((depth - start) / width, 1.0) : 0.0;
    }
    INFO("cascade ", want, "'s band starts at ", start, " and is ", width, " deep (0: the last cascade)");
    if (!CHECK_NEAR(b.nextWeight, weight, kApprox)) break;
  }
}

// Graders for lesson 06 (make grade LESSON=06): the public cases. Expected values are worked out by hand
// in the comments; the randomised cases compare with the reference implementation (compiled into
// the course library). More cases, with seeds the grader chooses, run when your work is graded.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "algorithms/texture_sampling.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using grading::kApprox;

namespace {
ImageF gray(int w, int h, std::initializer_list<float> values) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = 1;
  img.data.assign(values.begin(), values.end());
  return img;
}
ImageF constant(int w, int h, int channels, float v) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.data.assign(std::size_t(w * h * channels), v);
  return img;
}
ImageF randomImage(std::mt19937_64& rng, int w, int h, int channels) {
  std::uniform_real_distribution<float> u(0, 1);
  ImageF img = constant(w, h, channels, 0);
  for (float& v : img.data) v = u(rng);
  return img;
}
}  // namespace

// ---- 06.1 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.1: the lecture's 256x64 chain has 9 levels") {
  // 256x64, 128x32, 64x16, 32x8, 16x4, 8x2, 4x1, 2x1, 1x1
  CHECK_EXACT(ex06::mipLevelCount(256, 64), 9);
}

TEST_CASE("ex06.1: square, thin and non-power-of-two sizes") {
  CHECK_EXACT(ex06::mipLevelCount(512, 512), 10);  // 2^9: levels 0..9
  CHECK_EXACT(ex06::mipLevelCount(1, 1024), 11);
  CHECK_EXACT(ex06::mipLevelCount(640, 480), 10);  // 640 320 160 80 40 20 10 5 2 1
  CHECK_EXACT(ex06::mipLevelCount(3, 3), 2);       // 3, 1
  CHECK_EXACT(ex06::mipLevelCount(1, 1), 1);
}

// ---- 06.2 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.2: a square chain costs 4/3 of its base, not 1.5") {
  // 256^2 RGBA8: (65536 + 16384 + 4096 + 1024 + 256 + 64 + 16 + 4 + 1) x 4 = 87381 x 4.
  CHECK_EXACT(ex06::mipChainBytes(256, 256, 4), 349524LL);
  CHECK_EXACT(ex06::mipChainBytes(1, 1, 4), 4LL);
}

TEST_CASE("ex06.2: a rectangular chain keeps its 1-wide levels") {
  // 256x64 x 1 byte: 16384 + 4096 + 1024 + 256 + 64 + 16 + 4 (4x1) + 2 (2x1) + 1 = 21847.
  CHECK_EXACT(ex06::mipChainBytes(256, 64, 1), 21847LL);
  // 4x1 RGB: 4 + 2 + 1 = 7 texels x 3 bytes.
  CHECK_EXACT(ex06::mipChainBytes(4, 1, 3), 21LL);
}

// ---- 06.3 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.3: one texel per pixel is level 0, four is level 2") {
  CHECK_NEAR(ex06::lodFromDerivatives({4.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}), 2.0f, kApprox);
  CHECK_NEAR(ex06::lodFromDerivatives({1.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}), 0.0f, kApprox);
}

TEST_CASE("ex06.3: Euclidean lengths, the larger axis, non-square textures") {
  // d/dx = (3, 4) texels: Px = 5; d/dy = 2 texels: rho = 5, lambda = log2 5.
  CHECK_NEAR(ex06::lodFromDerivatives({3.0f / 64, 4.0f / 64}, {0, 2.0f / 64}, {64, 64}), std::log2(5.0f), kApprox);
  // 0.5 texels along x of a 512-wide texture; 8 texels along y of a 128-high one: log2 8 = 3.
  CHECK_NEAR(ex06::lodFromDerivatives({1.0f / 1024, 0}, {0, 8.0f / 128}, {512, 128}), 3.0f, kApprox);
  // Magnification: a quarter texel per pixel, lambda = -2.
  CHECK_NEAR(ex06::lodFromDerivatives({0.25f / 16, 0}, {0, 0.25f / 16}, {16, 16}), -2.0f, kApprox);
}

// ---- 06.4 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.4: bilinear between texel centres of a 2x2 image") {
  const ImageF img = gray(2, 2, {0, 1, 2, 3});  // (0,0)=0 (1,0)=1 (0,1)=2 (1,1)=3
  INFO("a 2x2 grey image: (0,0) = 0, (1,0) = 1, (0,1) = 2, (1,1) = 3");
  // At the centre of texel (0,0): exactly 0. Halfway between all four: 1.5.
  CHECK_NEAR(ex06::sampleBilinear(img, {0.25f, 0.25f}), glm::vec4(0, 0, 0, 1), 1e-4);
  CHECK_NEAR(ex06::sampleBilinear(img, {0.5f, 0.5f}), glm::vec4(1.5f, 0, 0, 1), 1e-4);
  // (0.375, 0.75): u' = 0.25 -> a = 0.25 on row 1 (v' = 1): 2 + 0.25 (3 - 2) = 2.25.
  CHECK_NEAR(ex06::sampleBilinear(img, {0.375f, 0.75f}), glm::vec4(2.25f, 0, 0, 1), 1e-4);
}

TEST_CASE("ex06.4: repeat wrapping at the edges, negative coordinates included") {
  const ImageF img = gray(2, 1, {0, 1});
  INFO("a 2x1 grey image: 0, 1");
  // u = 0: halfway between texel -1 (= texel 1 = 1) and texel 0 (= 0): 0.5.
  CHECK_NEAR(ex06::sampleBilinear(img, {0.0f, 0.5f}).x, 0.5f, kApprox);
  // u = -0.125: u' = -0.75, i0 = -1 (= 1), a = 0.25: 0.75 * 1 + 0.25 * 0 = 0.75.
  CHECK_NEAR(ex06::sampleBilinear(img, {-0.125f, 0.5f}).x, 0.75f, kApprox);
  // One whole period further gives the same.
  CHECK_NEAR(ex06::sampleBilinear(img, {1.875f, 3.5f}).x, 0.75f, kApprox);
}

TEST_CASE("ex06.4: every channel is filtered") {
  ImageF img = constant(2, 2, 4, 0.0f);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      img.at(x, y, 0) = float(x);
      img.at(x, y, 1) = float(y);
      img.at(x, y, 2) = 0.5f;
      img.at(x, y, 3) = float(x + y) / 2;
    }
  INFO("RGBA 2x2: r = x, g = y, b = 0.5, a = (x + y) / 2");
  // At (0.5, 0.5) every texel weighs 1/4: (0.5, 0.5, 0.5, 0.5).
  CHECK_NEAR(ex06::sampleBilinear(img, {0.5f, 0.5f}), glm::vec4(0.5f), 1e-4);
}

TEST_CASE("ex06.4: random images and coordinates against the reference") {
  std::mt19937_64 rng(test::seedFor("ex06.4"));
  std::uniform_real_distribution<float> u(-2, 3);
  for (int i = 0; i < 200; ++i) {
    const int w = 1 + int(rng() % 9), h = 1 + int(rng() % 9), channels = 1 + int(rng() % 4);
    const ImageF img = randomImage(rng, w, h, channels);
    const glm::vec2 uv(u(rng), u(rng));
    INFO("random case ", i, " of 200 (seed ", test::seed(), "): a random ", w, "x", h, " image, ", channels,
         " channels");
    CAPTURE(uv);
    if (!CHECK_NEAR(ex06::sampleBilinear(img, uv), sampling::sampleBilinear(img, uv), 1e-4)) break;
  }
}

// ---- 06.5 ----------------------------------------------------------------------------------------
namespace {
// Levels that are constants 0, 1, 2: the sample IS the blend weight of the levels.
std::vector<ImageF> levelChain() { return {constant(4, 4, 1, 0), constant(2, 2, 1, 1), constant(1, 1, 1, 2)}; }
}  // namespace

TEST_CASE("ex06.5: trilinear blends two levels by frac(lambda)") {
  const auto chain = levelChain();
  INFO("levels 4x4, 2x2, 1x1 holding the constants 0, 1, 2");
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, 0.25f).x, 0.25f, kApprox);  // 3/4 L0 + 1/4 L1
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, 1.5f).x, 1.5f, kApprox);    // 1/2 L1 + 1/2 L2
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, 1.0f).x, 1.0f, kApprox);
}

TEST_CASE("ex06.5: magnification and the last level") {
  const auto chain = levelChain();
  INFO("levels 4x4, 2x2, 1x1 holding the constants 0, 1, 2");
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, 2.0f).x, 2.0f, kApprox);
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, 7.5f).x, 2.0f, kApprox);
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.3f, 0.6f}, -3.0f).x, 0.0f, kApprox);
}

TEST_CASE("ex06.5: bilinear inside each level") {
  // Level 0: 2x1 ramp (0, 1); level 1: 1x1 of 4. At u = 0.375, level 0 gives 0.25 (ex06.4);
  // lambda = 0.5: 0.5 * 0.25 + 0.5 * 4 = 2.125.
  const std::vector<ImageF> chain{gray(2, 1, {0, 1}), gray(1, 1, {4})};
  CHECK_NEAR(ex06::sampleTrilinear(chain, {0.375f, 0.5f}, 0.5f).x, 2.125f, kApprox);
}

// ---- 06.6 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.6: a 4:1 footprint takes 4 probes at level 0") {
  const ex06::AnisoProbes p = ex06::anisotropicProbes({4.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}, 16);
  CHECK_EXACT(p.count, 4);
  CHECK_NEAR(p.lambda, 0.0f, kApprox);  // log2(4 / 4)
}

TEST_CASE("ex06.6: capped by maxAniso, ceil of the ratio, either axis major") {
  // Same 4:1 footprint at 2x: N = 2, lambda' = log2(4 / 2) = 1.
  ex06::AnisoProbes p = ex06::anisotropicProbes({4.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}, 2);
  CHECK_EXACT(p.count, 2);
  CHECK_NEAR(p.lambda, 1.0f, kApprox);
  // Px = |(3, 4)| = 5, Py = 2: ratio 2.5 -> N = 3, lambda' = log2(5 / 3).
  p = ex06::anisotropicProbes({3.0f / 64, 4.0f / 64}, {0, 2.0f / 64}, {64, 64}, 16);
  CHECK_EXACT(p.count, 3);
  CHECK_NEAR(p.lambda, std::log2(5.0f / 3.0f), kApprox);
  // Major along y: Px = 0.5, Py = 12 -> ratio 24, capped at 16; lambda' = log2(12 / 16).
  p = ex06::anisotropicProbes({0.5f / 64, 0}, {0, 12.0f / 64}, {64, 64}, 16);
  CHECK_EXACT(p.count, 16);
  CHECK_NEAR(p.lambda, std::log2(0.75f), kApprox);
  // Isotropic: one probe at the usual lambda (2 texels -> 1).
  p = ex06::anisotropicProbes({2.0f / 32, 0}, {0, 2.0f / 32}, {32, 32}, 16);
  CHECK_EXACT(p.count, 1);
  CHECK_NEAR(p.lambda, 1.0f, kApprox);
}

TEST_CASE("ex06.6: a line footprint (Pmin = 0) takes maxAniso probes") {
  const ex06::AnisoProbes p = ex06::anisotropicProbes({8.0f / 64, 0}, {0, 0}, {64, 64}, 8);
  CHECK_EXACT(p.count, 8);
  CHECK_NEAR(p.lambda, 0.0f, kApprox);  // log2(8 / 8)
}

TEST_CASE("ex06.6: random footprints against the reference") {
  std::mt19937_64 rng(test::seedFor("ex06.6"));
  std::uniform_real_distribution<float> d(-0.05f, 0.05f);
  for (int i = 0; i < 300; ++i) {
    const glm::vec2 dx(d(rng), d(rng)), dy(d(rng), d(rng));
    const glm::ivec2 size(64 << (i % 3), 32 << (i % 4));
    const int maxAniso = 1 + i % 16;
    const sampling::Footprint f = sampling::footprint(dx, dy, size, float(maxAniso));
    const float ratio = f.pmin > 0 ? f.pmax / f.pmin : 0;
    if (f.pmin < 1e-4f || ratio > 1e4f || std::abs(ratio - std::round(ratio)) < 1e-3f) continue;  // ceil at ties
    const ex06::AnisoProbes p = ex06::anisotropicProbes(dx, dy, size, maxAniso);
    INFO("random case ", i, " of 300 (seed ", test::seed(), "): maxAniso ", maxAniso);
    CAPTURE(dx);
    CAPTURE(dy);
    CAPTURE(size);
    if (!CHECK_EXACT(p.count, f.probes) || !CHECK_NEAR(p.lambda, f.lambdaAniso, grading::relativeTolerance(1e-3)))
      break;
  }
}

// ---- 06.7 ----------------------------------------------------------------------------------------
TEST_CASE("ex06.7: 4x2 to 2x1, each texel the mean of its 2x2 parents") {
  const ImageF out = ex06::boxDownsample(gray(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}));
  INFO("a 4x2 grey image: 0 1 2 3 / 4 5 6 7");
  if (!CHECK_EXACT(glm::ivec3(out.width, out.height, out.channels), glm::ivec3(2, 1, 1))) return;
  REQUIRE(out.data.size() == 2u);
  CHECK_NEAR(out.at(0, 0), 2.5f, kApprox);  // (0 + 1 + 4 + 5) / 4
  CHECK_NEAR(out.at(1, 0), 4.5f, kApprox);  // (2 + 3 + 6 + 7) / 4
}

TEST_CASE("ex06.7: a side already 1 stays 1, channels kept") {
  const ImageF a = ex06::boxDownsample(gray(1, 4, {0, 1, 2, 3}));
  INFO("a 1x4 grey column 0 1 2 3, then an RGBA 2x2 whose blue is 0 1 2 3");
  if (!CHECK_EXACT(glm::ivec3(a.width, a.height, int(a.data.size())), glm::ivec3(1, 2, 2))) return;
  CHECK_NEAR(a.at(0, 0), 0.5f, kApprox);
  CHECK_NEAR(a.at(0, 1), 2.5f, kApprox);
  ImageF rgba = constant(2, 2, 4, 0.0f);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) rgba.at(x, y, 2) = float(x + 2 * y);  // blue 0 1 2 3
  const ImageF b = ex06::boxDownsample(rgba);
  if (!CHECK_EXACT(glm::ivec4(b.width, b.height, b.channels, int(b.data.size())), glm::ivec4(1, 1, 4, 4))) return;
  CHECK_NEAR(b.at(0, 0, 2), 1.5f, kApprox);
  CHECK_NEAR(b.at(0, 0, 0), 0.0f, kApprox);
}

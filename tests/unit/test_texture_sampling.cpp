// The CPU texture sampler of lesson 06 (algorithms/texture_sampling): every expected value is worked out
// by hand in the comment next to it, from the GL 4.6 spec (8.14) and EXT_texture_filter_anisotropic.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "algorithms/texture_sampling.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::sampling;

namespace {
// A one-channel image from values, row 0 first.
ImageF gray(int w, int h, std::initializer_list<float> values) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = 1;
  img.data.assign(values.begin(), values.end());
  REQUIRE(img.data.size() == std::size_t(w * h));
  return img;
}
ImageF constant(int w, int h, float v) {
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = 1;
  img.data.assign(std::size_t(w * h), v);
  return img;
}
// A chain whose levels are constants 0, 1, 2 (4x4, 2x2, 1x1): the sample IS the blend of levels.
std::vector<ImageF> levelChain() { return {constant(4, 4, 0), constant(2, 2, 1), constant(1, 1, 2)}; }
}  // namespace

TEST_CASE("texture sampling: mip level count halves to 1x1") {
  CHECK(mipLevelCount(1, 1) == 1);
  CHECK(mipLevelCount(256, 64) == 9);  // the lecture's chain: 256x64 ... 2x1, 1x1
  CHECK(mipLevelCount(1024, 1) == 11);
  CHECK(mipLevelCount(640, 480) == 10);  // 640 320 160 80 40 20 10 5 2 1
  CHECK(mipLevelSize(256, 64, 6) == glm::ivec2(4, 1));
  CHECK(mipLevelSize(256, 64, 7) == glm::ivec2(2, 1));
  CHECK_THROWS_AS(mipLevelCount(0, 4), std::invalid_argument);
  CHECK_THROWS_AS(mipLevelSize(4, 4, 3), std::invalid_argument);
}

TEST_CASE("texture sampling: a mip chain costs 4/3 of its base, a RIP map 4x") {
  // 256^2: 65536 + 16384 + 4096 + 1024 + 256 + 64 + 16 + 4 + 1 = 87381 texels, x4 bytes.
  CHECK(mipChainBytes(256, 256, 4) == 349524u);
  CHECK(double(mipChainBytes(256, 256, 1)) / 65536.0 == doctest::Approx(4.0 / 3.0).epsilon(1e-4));
  // The lecture's 256x64: 16384 + 4096 + 1024 + 256 + 64 + 16 + 4 + 2 + 1 = 21847.
  CHECK(mipChainBytes(256, 64, 1) == 21847u);
  // RIP: (sum of widths) x (sum of heights) = 511 x 511 for 256^2, about 4x the base.
  CHECK(ripMapBytes(256, 256, 1) == 261121u);
  CHECK(ripMapBytes(4, 2, 1) == 21u);  // (4 + 2 + 1) x (2 + 1)
  // The lecture's 3D texture: 256^3 x 4 bytes = 64 MiB.
  CHECK(volumeBytes(256, 256, 256, 4) == 64ull * 1024 * 1024);
}

TEST_CASE("texture sampling: box downsample averages 2x2 parents") {
  const ImageF a = boxDownsample(gray(2, 2, {0, 1, 2, 3}));
  REQUIRE(a.width == 1);
  CHECK(a.at(0, 0) == doctest::Approx(1.5f));
  // 4x2 -> 2x1: (0+1+4+5)/4 = 2.5, (2+3+6+7)/4 = 4.5
  const ImageF b = boxDownsample(gray(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}));
  REQUIRE((b.width == 2 && b.height == 1));
  CHECK(b.at(0, 0) == doctest::Approx(2.5f));
  CHECK(b.at(1, 0) == doctest::Approx(4.5f));
  // A 1-wide image only halves vertically: (0+1)/2, (2+3)/2.
  const ImageF c = boxDownsample(gray(1, 4, {0, 1, 2, 3}));
  REQUIRE((c.width == 1 && c.height == 2));
  CHECK(c.at(0, 1) == doctest::Approx(2.5f));
  // RIP halving: one axis only.
  CHECK(boxDownsampleX(gray(2, 2, {0, 1, 2, 3})).at(0, 1) == doctest::Approx(2.5f));
  CHECK(boxDownsampleY(gray(2, 2, {0, 1, 2, 3})).at(1, 0) == doctest::Approx(2.0f));
  CHECK_THROWS_AS(boxDownsample(ImageF{}), std::invalid_argument);
  CHECK(buildMipChain(constant(4, 2, 1)).size() == 3u);  // 4x2, 2x1, 1x1
}

TEST_CASE("texture sampling: RIP atlas layout") {
  const RipAtlas r = buildRipAtlas(gray(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}));
  CHECK(r.atlas.width == 7);   // 4 + 2 + 1
  CHECK(r.atlas.height == 3);  // 2 + 1
  CHECK(r.offsetX == std::vector<int>{0, 4, 6});
  CHECK(r.offsetY == std::vector<int>{0, 2});
  CHECK(r.levelSize(1, 1) == glm::ivec2(2, 1));
  CHECK(r.atlas.at(4, 1) == doctest::Approx(4.5f));  // level (1,0) texel (0,1): (4+5)/2
  CHECK(r.atlas.at(1, 2) == doctest::Approx(3.0f));  // level (0,1) texel (1,0): (1+5)/2
  CHECK(r.atlas.at(6, 2) == doctest::Approx(3.5f));  // level (2,1): the mean of all
}

TEST_CASE("texture sampling: the four wrap modes") {
  CHECK(wrapIndex(-1, 4, Wrap::Repeat) == 3);
  CHECK(wrapIndex(4, 4, Wrap::Repeat) == 0);
  // Mirrored, period 2n = 8: 0 1 2 3 | 3 2 1 0 | 0 ...; -1..-4 -> 0 1 2 3.
  CHECK(wrapIndex(4, 4, Wrap::MirroredRepeat) == 3);
  CHECK(wrapIndex(5, 4, Wrap::MirroredRepeat) == 2);
  CHECK(wrapIndex(8, 4, Wrap::MirroredRepeat) == 0);
  CHECK(wrapIndex(-1, 4, Wrap::MirroredRepeat) == 0);
  CHECK(wrapIndex(-5, 4, Wrap::MirroredRepeat) == 3);
  CHECK(wrapIndex(-3, 4, Wrap::ClampToEdge) == 0);
  CHECK(wrapIndex(9, 4, Wrap::ClampToEdge) == 3);
  CHECK(wrapIndex(4, 4, Wrap::ClampToBorder) == -1);
  CHECK(wrapIndex(2, 4, Wrap::ClampToBorder) == 2);
}

TEST_CASE("texture sampling: nearest and bilinear on a 2x1 ramp") {
  const ImageF img = gray(2, 1, {0, 1});  // texel centres at u = 0.25 and 0.75
  CHECK(sampleNearest(img, {0.49f, 0.5f}).x == 0.0f);
  CHECK(sampleNearest(img, {0.51f, 0.5f}).x == 1.0f);
  CHECK(sampleBilinear(img, {0.25f, 0.5f}).x == doctest::Approx(0.0f));
  CHECK(sampleBilinear(img, {0.5f, 0.5f}).x == doctest::Approx(0.5f));
  CHECK(sampleBilinear(img, {0.375f, 0.5f}).x == doctest::Approx(0.25f));  // u' - 1/2 = 0.25
  // At u = 0, halfway between texel -1 and texel 0:
  CHECK(sampleBilinear(img, {0.0f, 0.5f}, Wrap::Repeat).x == doctest::Approx(0.5f));       // texel -1 is 1
  CHECK(sampleBilinear(img, {0.0f, 0.5f}, Wrap::ClampToEdge).x == doctest::Approx(0.0f));  // texel -1 is 0
  CHECK(sampleBilinear(img, {0.0f, 0.5f}, Wrap::MirroredRepeat).x == doctest::Approx(0.0f));
  CHECK(sampleBilinear(img, {0.0f, 0.5f}, Wrap::ClampToBorder, Wrap::Repeat, glm::vec4(0.8f)).x ==
        doctest::Approx(0.4f));
  // Missing channels read 0, alpha 1.
  CHECK(sampleNearest(img, {0.9f, 0.5f}) == glm::vec4(1, 0, 0, 1));
}

TEST_CASE("texture sampling: bilinear on a 2x2 image, both axes") {
  // Texels (0,0)=0 (1,0)=1 (0,1)=2 (1,1)=3; at uv (0.5, 0.5) the weights are 1/4 each: 1.5.
  CHECK(sampleBilinear(gray(2, 2, {0, 1, 2, 3}), {0.5f, 0.5f}).x == doctest::Approx(1.5f));
  // At (0.5, 0.25): the bottom row only, halfway: 0.5.
  CHECK(sampleBilinear(gray(2, 2, {0, 1, 2, 3}), {0.5f, 0.25f}).x == doctest::Approx(0.5f));
}

TEST_CASE("texture sampling: level selection of the four mipmap modes") {
  const auto chain = levelChain();
  SamplerState s;                                                               // trilinear
  CHECK(sampleLod(chain, {0.3f, 0.3f}, -1.0f, s).x == doctest::Approx(0.0f));   // magnification: level 0
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 0.25f, s).x == doctest::Approx(0.25f));  // 3/4 level 0 + 1/4 level 1
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 1.5f, s).x == doctest::Approx(1.5f));
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 5.0f, s).x == doctest::Approx(2.0f));  // clamped to q = 2
  s.mip = MipFilter::Nearest;  // d = ceil(lambda + 1/2) - 1, 0 for lambda <= 1/2
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 0.5f, s).x == doctest::Approx(0.0f));
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 0.6f, s).x == doctest::Approx(1.0f));
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 1.5f, s).x == doctest::Approx(1.0f));
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 1.51f, s).x == doctest::Approx(2.0f));
  s.mip = MipFilter::None;  // no mipmaps: always level 0
  CHECK(sampleLod(chain, {0.3f, 0.3f}, 1.5f, s).x == doctest::Approx(0.0f));
  CHECK_THROWS_AS(sampleLod({}, {0, 0}, 0, s), std::invalid_argument);
}

TEST_CASE("texture sampling: footprint, lambda and anisotropic probes") {
  // One texel per pixel on both axes: lambda 0, one probe.
  Footprint f = footprint({1.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}, 16);
  CHECK(f.lambda == doctest::Approx(0.0f));
  CHECK(f.probes == 1);
  // 4 texels along x, 1 along y: isotropic lambda = log2 4 = 2; N = ceil(4/1) = 4, lambda' = log2(4/4) = 0.
  f = footprint({4.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}, 16);
  CHECK(f.lambda == doctest::Approx(2.0f));
  CHECK(f.probes == 4);
  CHECK(f.lambdaAniso == doctest::Approx(0.0f));
  CHECK(f.majorIsX);
  // Capped at 2x: N = 2, lambda' = log2(4/2) = 1.
  f = footprint({4.0f / 256, 0}, {0, 1.0f / 256}, {256, 256}, 2);
  CHECK(f.probes == 2);
  CHECK(f.lambdaAniso == doctest::Approx(1.0f));
  // Px = |(3, 4)| = 5 texels, Py = 2 (major along y? no: 5 > 2): N = ceil(2.5) = 3, lambda' = log2(5/3).
  f = footprint({3.0f / 64, 4.0f / 64}, {0, 2.0f / 64}, {64, 64}, 16);
  CHECK(f.px == doctest::Approx(5.0f));
  CHECK(f.probes == 3);
  CHECK(f.lambdaAniso == doctest::Approx(std::log2(5.0f / 3.0f)));
  // Major along y.
  f = footprint({0.5f / 64, 0}, {0, 4.0f / 64}, {64, 64}, 16);
  CHECK_FALSE(f.majorIsX);
  CHECK(f.probes == 8);
  // Degenerate: a line footprint takes the cap; no footprint is magnification.
  CHECK(footprint({1.0f / 8, 0}, {0, 0}, {8, 8}, 16).probes == 16);
  CHECK(std::isinf(lodFromDerivatives({0, 0}, {0, 0}, {8, 8})));
  // A non-square texture: 2 texels along u of a 512-wide texture, 0.5 along v of a 128-high one.
  CHECK(lodFromDerivatives({2.0f / 512, 0}, {0, 0.5f / 128}, {512, 128}) == doctest::Approx(1.0f));
}

TEST_CASE("texture sampling: anisotropic probes along the major axis") {
  // 8x1 texture with texel i = i^2, nearest filtering. Footprint 4 texels along x: N = 4 probes at
  // u = 0.5 + 0.5 (i/5 - 1/2) = 0.35, 0.45, 0.55, 0.65 -> texels 2, 3, 4, 5 -> (4 + 9 + 16 + 25) / 4.
  const std::vector<ImageF> chain{gray(8, 1, {0, 1, 4, 9, 16, 25, 36, 49})};
  SamplerState s;
  s.mag = s.min = Filter::Nearest;
  s.maxAniso = 16;
  CHECK(sample(chain, {0.5f, 0.5f}, {0.5f, 0}, {0, 1.0f}, s).x == doctest::Approx(13.5f));
  s.maxAniso = 1;  // one sample at the centre: texel 4, lambda = 2 but only one level
  CHECK(sample(chain, {0.5f, 0.5f}, {0.5f, 0}, {0, 1.0f}, s).x == doctest::Approx(16.0f));
}

TEST_CASE("texture sampling: the best filter is trilinear at 16x with no bias, wrap and border kept") {
  SamplerState s;
  s.mag = s.min = Filter::Nearest;
  s.mip = MipFilter::None;
  s.wrapS = Wrap::ClampToBorder;
  s.wrapT = Wrap::MirroredRepeat;
  s.border = {1.0f, 0.2f, 0.6f, 1.0f};
  s.lodBias = -2.5f;
  s.maxAniso = 2;
  const SamplerState b = bestFilter(s);
  CHECK(b.mag == Filter::Linear);
  CHECK(b.min == Filter::Linear);
  CHECK(b.mip == MipFilter::Linear);
  CHECK(b.maxAniso == 16.0f);
  CHECK(b.lodBias == 0.0f);
  CHECK(b.wrapS == Wrap::ClampToBorder);
  CHECK(b.wrapT == Wrap::MirroredRepeat);
  CHECK(b.border == glm::vec4(1.0f, 0.2f, 0.6f, 1.0f));
}

TEST_CASE("texture sampling: the full path agrees with the level it picks") {
  const auto chain = buildMipChain(makeZonePlate(64));
  SamplerState s;
  const glm::vec2 uv(0.3f, 0.7f);
  // 2 texels per pixel -> lambda = 1 exactly: level 1, bilinear.
  const glm::vec4 a = sample(chain, uv, {2.0f / 64, 0}, {0, 2.0f / 64}, s);
  const glm::vec4 b = sampleBilinear(chain[1], uv);
  CHECK(a.x == doctest::Approx(b.x));
  // LOD bias +1 from 1 texel per pixel: the same level 1.
  s.lodBias = 1;
  CHECK(sample(chain, uv, {1.0f / 64, 0}, {0, 1.0f / 64}, s).x == doctest::Approx(b.x));
}

TEST_CASE("texture sampling: random samples stay within the texels they blend") {
  std::mt19937_64 rng(test::seedFor("texture_sampling.bounds"));
  std::uniform_real_distribution<float> u(-2, 3), d(0, 0.3f);
  const auto chain = buildMipChain(toFloat(toImage8(makeZonePlate(32))));
  for (int i = 0; i < 500; ++i) {
    SamplerState s;
    s.wrapS = Wrap(i % 4);
    s.wrapT = Wrap((i / 4) % 4);
    s.maxAniso = float(1 + i % 16);
    s.border = glm::vec4(0.5f);
    const glm::vec4 v = sample(chain, {u(rng), u(rng)}, {d(rng), d(rng)}, {d(rng), d(rng)}, s);
    CHECK((v.x >= -1e-5f && v.x <= 1 + 1e-5f));
    CHECK(std::isfinite(v.y));
  }
}

TEST_CASE("texture sampling: projections") {
  CHECK(planarUv({1, 2, 3}) == glm::vec2(1, 3));
  CHECK(cylindricalUv({0, 5, 1}).x == doctest::Approx(0.0f));
  CHECK(cylindricalUv({0, 5, 1}).y == doctest::Approx(5.0f));
  CHECK(cylindricalUv({1, 0, 0}).x == doctest::Approx(0.25f));   // phi = pi/2
  CHECK(cylindricalUv({0, 0, -1}).x == doctest::Approx(0.5f));   // phi = pi
  CHECK(cylindricalUv({-1, 0, 0}).x == doctest::Approx(0.75f));  // phi = 3pi/2
  CHECK(sphericalUv({0, 1, 0}).y == doctest::Approx(0.0f));      // north pole
  CHECK(sphericalUv({0, -2, 0}).y == doctest::Approx(1.0f));     // south pole
  CHECK(sphericalUv({1, 0, 0}) == glm::vec2(0.25f, 0.5f));
  CHECK(sphericalUv({0, 0, 0}) == glm::vec2(0, 0));
}

TEST_CASE("texture sampling: zone plate and 8-bit round trip") {
  const ImageF z = makeZonePlate(16);
  CHECK(z.at(8, 8, 0) > 0.99f);  // r^2 = 0.5 at the centre texel: cos(pi 0.5 / 16) ~ 0.995
  CHECK(z.at(0, 0, 3) == 1.0f);
  const Image8 b = toImage8(z);
  CHECK(toFloat(b).at(8, 8, 0) == doctest::Approx(254.0f / 255.0f).epsilon(0.01));
}

TEST_CASE("texture sampling: supersampled reference figures") {
  Image8 img;
  img.width = 4;
  img.height = 2;
  img.channels = 4;
  img.data.assign(4 * 2 * 4, 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) img.at(x, y)[0] = std::uint8_t(10 * (x + 4 * y));  // red 0 10 20 30 / 40 50 60 70
  // 2x2 blocks: (0 + 10 + 40 + 50) / 4 = 25, (20 + 30 + 60 + 70) / 4 = 45.
  const std::vector<float> r = boxReduceRgb(img, 2);
  REQUIRE(r.size() == 6u);
  CHECK(r[0] == doctest::Approx(25.0f));
  CHECK(r[3] == doctest::Approx(45.0f));
  CHECK(r[1] == 0.0f);
  CHECK_THROWS_AS(boxReduceRgb(img, 3), std::invalid_argument);
  // Differences (3, 4) and (0, 0): RMSE sqrt((9 + 16) / 4) = 2.5; mean |.| = 7 / 4.
  CHECK(rmse({3, 4, 0, 0}, {0, 0, 0, 0}) == doctest::Approx(2.5));
  CHECK(meanAbsDifference({3, -4, 0, 0}, {0, 0, 0, 0}) == doctest::Approx(1.75));
  CHECK(meanAbsDifference({1}, {}) == -1.0);
  const std::vector<std::uint8_t> v = makeShellVolume(8);
  CHECK(v.size() == 8u * 8 * 8 * 4);
  CHECK(v[3] == 255);
  CHECK_THROWS_AS(makeShellVolume(0), std::invalid_argument);
}

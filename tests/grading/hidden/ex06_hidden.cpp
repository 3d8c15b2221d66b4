// Hidden cases for lesson 06 (instructor tree only): the GL specification's and the extension's
// formulas written out independently of the reference (the reference itself for trilinear), with
// the seed the grader chooses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "algorithms/texture_sampling.hpp"
#include "exercises.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
ImageF randomImage(std::mt19937_64& rng, int w, int h, int channels) {
  std::uniform_real_distribution<float> u(0, 1);
  ImageF img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.data.resize(std::size_t(w * h * channels));
  for (float& v : img.data) v = u(rng);
  return img;
}
}  // namespace

TEST_SUITE("hidden") {
  TEST_CASE("ex06.1: random sizes: halve until 1x1") {
    std::mt19937_64 rng(test::seedFor("ex06.1 hidden"));
    for (int i = 0; i < 200; ++i) {
      int w = 1 + int(rng() % 5000), h = 1 + int(rng() % 300), levels = 1;
      const int w0 = w, h0 = h;
      while (w > 1 || h > 1) w = std::max(1, w / 2), h = std::max(1, h / 2), ++levels;
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): ", w0, "x", h0);
      if (!CHECK_EXACT(ex06::mipLevelCount(w0, h0), levels)) break;
    }
  }

  TEST_CASE("ex06.2: random sizes: the sum over the chain") {
    std::mt19937_64 rng(test::seedFor("ex06.2 hidden"));
    for (int i = 0; i < 200; ++i) {
      const int w0 = 1 + int(rng() % 3000), h0 = 1 + int(rng() % 3000), bpp = 1 + int(rng() % 16);
      long long bytes = 0;
      for (int w = w0, h = h0;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
        bytes += (long long)w * h * bpp;
        if (w == 1 && h == 1) break;
      }
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): ", w0, "x", h0, " at ", bpp, " bytes a texel");
      if (!CHECK_EXACT(ex06::mipChainBytes(w0, h0, bpp), bytes)) break;
    }
  }

  TEST_CASE("ex06.3: random derivatives: log2 of the longer footprint axis in texels") {
    std::mt19937_64 rng(test::seedFor("ex06.3 hidden"));
    std::uniform_real_distribution<float> d(-0.05f, 0.05f);
    for (int i = 0; i < 300; ++i) {
      const glm::vec2 dx(d(rng), d(rng)), dy(d(rng), d(rng));
      const glm::ivec2 size(16 << (i % 5), 16 << ((i / 5) % 5));
      const glm::vec2 s(size);
      const float rho = std::max(glm::length(dx * s), glm::length(dy * s));
      INFO("random case ", i, " of 300 (seed ", test::seed(), ")");
      CAPTURE(dx);
      CAPTURE(dy);
      CAPTURE(size);
      if (!CHECK_NEAR(ex06::lodFromDerivatives(dx, dy, size), std::log2(rho), 1e-4)) break;
    }
  }

  TEST_CASE("ex06.4: random images: the four weighted texels, repeat wrapped") {
    std::mt19937_64 rng(test::seedFor("ex06.4 hidden"));
    std::uniform_real_distribution<float> u(-3, 4);
    for (int i = 0; i < 200; ++i) {
      const int w = 1 + int(rng() % 7), h = 1 + int(rng() % 7), channels = 1 + int(rng() % 4);
      const ImageF img = randomImage(rng, w, h, channels);
      const glm::vec2 uv(u(rng), u(rng));
      const float x = uv.x * float(w) - 0.5f, y = uv.y * float(h) - 0.5f;
      const int i0 = int(std::floor(x)), j0 = int(std::floor(y));
      const float a = x - float(i0), b = y - float(j0);
      auto texel = [&](int ti, int tj) {
        ti = ((ti % w) + w) % w, tj = ((tj % h) + h) % h;
        glm::vec4 t(0, 0, 0, 1);
        for (int c = 0; c < channels; ++c) t[c] = img.at(ti, tj, c);
        return t;
      };
      const glm::vec4 expected = (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0 + 1, j0) +
                                 (1 - a) * b * texel(i0, j0 + 1) + a * b * texel(i0 + 1, j0 + 1);
      INFO("random case ", i, " of 200 (seed ", test::seed(), "): a random ", w, "x", h, " image, ", channels,
           " channels");
      CAPTURE(uv);
      if (!CHECK_NEAR(ex06::sampleBilinear(img, uv), expected, 1e-4)) break;
    }
  }

  TEST_CASE("ex06.5: random chains and lambdas against the reference's GL_LINEAR_MIPMAP_LINEAR") {
    std::mt19937_64 rng(test::seedFor("ex06.5 hidden"));
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 100; ++i) {
      std::vector<ImageF> chain;
      for (int s = 16; s >= 1; s /= 2) chain.push_back(randomImage(rng, s, s, 3));
      const glm::vec2 uv(3 * u(rng) - 1, 3 * u(rng) - 1);
      const float lambda = 7 * u(rng) - 1.5f;
      INFO("random case ", i, " of 100 (seed ", test::seed(), "): random RGB chain 16x16 .. 1x1, lambda ", lambda);
      CAPTURE(uv);
      if (!CHECK_NEAR(ex06::sampleTrilinear(chain, uv, lambda),
                      sampling::sampleLod(chain, uv, lambda, sampling::SamplerState{}), 1e-4))
        break;
    }
  }

  TEST_CASE("ex06.6: random footprints against the extension's formulas") {
    std::mt19937_64 rng(test::seedFor("ex06.6 hidden"));
    std::uniform_real_distribution<float> d(-0.05f, 0.05f);
    for (int i = 0; i < 300; ++i) {
      const glm::vec2 dx(d(rng), d(rng)), dy(d(rng), d(rng));
      const glm::ivec2 size(64 << (i % 3), 32 << (i % 4));
      const int maxAniso = 1 + i % 16;
      const double px = std::hypot(double(dx.x) * size.x, double(dx.y) * size.y);
      const double py = std::hypot(double(dy.x) * size.x, double(dy.y) * size.y);
      const double pmax = std::max(px, py), pmin = std::min(px, py);
      if (pmin < 1e-4 || pmax / pmin > 1e4) continue;
      const double ratio = pmax / pmin;
      if (std::abs(ratio - std::round(ratio)) < 1e-3) continue;  // ceil is ill-conditioned at integers
      const int n = int(std::min(std::ceil(ratio), double(maxAniso)));
      const ex06::AnisoProbes p = ex06::anisotropicProbes(dx, dy, size, maxAniso);
      INFO("random case ", i, " of 300 (seed ", test::seed(), "): maxAniso ", maxAniso);
      CAPTURE(dx);
      CAPTURE(dy);
      CAPTURE(size);
      if (!CHECK_EXACT(p.count, n) || !CHECK_NEAR(p.lambda, std::log2(pmax / n), grading::relativeTolerance(1e-3)))
        break;
    }
  }

  TEST_CASE("ex06.7: random images: every texel the mean of its parents") {
    std::mt19937_64 rng(test::seedFor("ex06.7 hidden"));
    for (int i = 0; i < 100; ++i) {
      const int w = 1 + int(rng() % 12), h = 1 + int(rng() % 12), channels = 1 + int(rng() % 4);
      const ImageF src = randomImage(rng, w, h, channels);
      const ImageF out = ex06::boxDownsample(src);
      const glm::ivec3 want(std::max(1, w / 2), std::max(1, h / 2), channels);
      INFO("random case ", i, " of 100 (seed ", test::seed(), "): a random ", w, "x", h, " image, ", channels,
           " channels");
      if (!CHECK_EXACT(glm::ivec3(out.width, out.height, out.channels), want)) break;
      bool ok = true;
      for (int y = 0; y < want.y && ok; ++y)
        for (int x = 0; x < want.x && ok; ++x)
          for (int c = 0; c < channels && ok; ++c) {
            const int x1 = w > 1 ? 2 * x + 1 : 0, y1 = h > 1 ? 2 * y + 1 : 0;
            const float mean = (src.at(2 * x * (w > 1), 2 * y * (h > 1), c) + src.at(x1, 2 * y * (h > 1), c) +
                                src.at(2 * x * (w > 1), y1, c) + src.at(x1, y1, c)) /
                               4.0f;
            INFO("texel (", x, ", ", y, ") channel ", c);
            ok = CHECK_NEAR(out.at(x, y, c), mean, 1e-5);
          }
      if (!ok) break;
    }
  }
}

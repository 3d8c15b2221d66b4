// Error and aliasing metrics on synthetic images whose answers are counted by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/ground_truth.hpp"
#include "measure/metrics.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;

namespace {

ImageF image(int w, int h, std::initializer_list<float> values, int channels = 1) {
  ImageF out;
  out.width = w;
  out.height = h;
  out.channels = channels;
  out.data.assign(values);
  REQUIRE(out.data.size() == std::size_t(w) * h * channels);
  return out;
}

const float NaN = std::numeric_limits<float>::quiet_NaN();

// Reference: columns 0-1 lit, 2-3 shadowed; (0,2) faces away, (3,2) is background.
ImageF reference() {
  return image(4, 3,
               {1, 1, 0, 0,  //
                1, 1, 0, 0,  //
                kNotFacing, 1, 0, kBackground});
}
// Technique: a false shadow at (1,0), leaks at (3,0) and (2,1); (0,2) differs but is not facing.
ImageF technique() {
  return image(4, 3,
               {0.7f, 0.3f, 0, 1,  //
                1, 1, 0.9f, 0,     //
                0, 1, 0, 0});
}

}  // namespace

TEST_CASE("measure.metrics: hard-shadow errors split into leaks and false shadows") {
  HardShadowErrors e = compareHard(technique(), reference());
  CHECK(e.facingPixels == 10);
  CHECK(e.referenceShadowed == 5);  // columns 2-3 of rows 0-1, and (2,2)
  CHECK(e.misclassified == 3);
  CHECK(e.leaks == 2);
  CHECK(e.falseShadows == 1);
  CHECK(e.misclassifiedPct == doctest::Approx(30.0));
  CHECK(e.leakPct == doctest::Approx(20.0));
  CHECK(e.falseShadowPct == doctest::Approx(10.0));
  // Columns 1 and 2 touch the lit/shadow boundary (6 facing pixels); of the other 4, (3,0) is wrong.
  CHECK(e.edgePixels == 6);
  CHECK(e.edgeTolerantMisclassified == 1);
  CHECK(e.edgeTolerantPct == doctest::Approx(25.0));

  // A threshold of 0.8 turns (0,0) = 0.7 into a false shadow as well.
  CHECK(compareHard(technique(), reference(), 0.8f).falseShadows == 2);
}

TEST_CASE("measure.metrics: an explicit facing mask decides which pixels count") {
  std::vector<std::uint8_t> all(12, 1);
  HardShadowErrors e = compareHard(technique(), reference(), all);
  // 12 pixels; the reference's negative marks count as shadowed: (0,2) and (3,2) agree with 0.
  CHECK(e.facingPixels == 12);
  CHECK(e.misclassified == 3);
  CHECK(e.misclassifiedPct == doctest::Approx(25.0));
  // (0,2) is now shadowed next to lit (0,1), (1,1), (1,2): it and (0,1) join the 6 edge pixels.
  CHECK(e.edgePixels == 8);
  CHECK(e.edgeTolerantPct == doctest::Approx(25.0));  // (3,0) of (0,0), (3,0), (3,1), (3,2)
  CHECK_THROWS_WITH_AS(compareHard(technique(), reference(), std::vector<std::uint8_t>(5, 1)),
                       doctest::Contains("5 entries"), std::invalid_argument);
}

TEST_CASE("measure.metrics: identical images have no error, and a mask converts to visibility") {
  HardShadowErrors e = compareHard(reference(), reference());
  CHECK(e.misclassified == 0);
  CHECK(e.misclassifiedPct == 0.0);
  Image8 mask;
  mask.width = 2;
  mask.height = 1;
  mask.channels = 1;
  mask.data = {255, 0};
  ImageF v = visibilityFromMask(mask);
  CHECK(v.data == std::vector<float>{1.0f, 0.0f});
  CHECK_THROWS_WITH_AS(visibilityFromMask(mask, 2), doctest::Contains("channel 2"), std::invalid_argument);
}

TEST_CASE("measure.metrics: soft-shadow RMSE and maximum error over facing pixels") {
  ImageF ref = image(4, 1, {0, 0.5f, 1, kNotFacing});
  ImageF tech = image(4, 1, {0.1f, 0.5f, 0.6f, 0.9f});
  SoftShadowErrors e = compareSoft(tech, ref);
  CHECK(e.pixels == 3);
  CHECK(e.rmse == doctest::Approx(std::sqrt((0.01 + 0.0 + 0.16) / 3)).epsilon(1e-6));
  CHECK(e.maxAbs == doctest::Approx(0.4).epsilon(1e-6));
}

TEST_CASE("measure.metrics: size mismatches throw naming both sizes") {
  ImageF small = image(2, 1, {0, 1});
  CHECK_THROWS_WITH_AS(compareHard(small, reference()), doctest::Contains("2x1x1"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(compareSoft(reference(), small), doctest::Contains("4x3x1"), std::invalid_argument);
  CHECK_THROWS_AS(hardErrorHeatmap(small, reference()), std::invalid_argument);
  ImageF twoChannels = image(1, 1, {0, 1}, 2);
  CHECK_THROWS_WITH_AS(aliasingStats(twoChannels), doctest::Contains("2 channels"), std::invalid_argument);
}

TEST_CASE("measure.metrics: the hard error heatmap colours leaks, false shadows and agreement") {
  Image8 map = hardErrorHeatmap(technique(), reference());
  REQUIRE(map.width == 4);
  REQUIRE(map.channels == 4);
  auto rgb = [&](int x, int y) {
    const std::uint8_t* p = map.at(x, y);
    return Rgb8{p[0], p[1], p[2]};
  };
  CHECK(rgb(3, 0) == kLeakColor);
  CHECK(rgb(2, 1) == kLeakColor);
  CHECK(rgb(1, 0) == kFalseShadowColor);
  Rgb8 agreeLit = rgb(0, 0), agreeShadow = rgb(2, 0);
  CHECK((agreeLit.r == agreeLit.g && agreeLit.g == agreeLit.b));  // grey
  CHECK((agreeShadow.r == agreeShadow.g && agreeShadow.g == agreeShadow.b));
  CHECK(agreeLit.r > agreeShadow.r);
  CHECK(map.at(3, 2)[3] == 0);  // background stays transparent
  CHECK(map.at(0, 0)[3] == 255);

  Image8 soft = softErrorHeatmap(image(2, 1, {1.0f, 0.0f}), image(2, 1, {0.5f, 0.5f}), 0.25f);
  CHECK(Rgb8{soft.at(0, 0)[0], soft.at(0, 0)[1], soft.at(0, 0)[2]} == kLeakColor);  // saturated: +0.5
  CHECK(Rgb8{soft.at(1, 0)[0], soft.at(1, 0)[1], soft.at(1, 0)[2]} == kFalseShadowColor);
}

TEST_CASE("measure.metrics: m is the inverse of J's smallest singular value") {
  // Scaling: J = diag(2, 0.5) stretches screen y to half a texel per pixel, so a texel spans 2 pixels.
  CHECK(aliasingFactor(glm::mat2(glm::vec2(2, 0), glm::vec2(0, 0.5f))) == doctest::Approx(2.0));
  // Rotations do not change singular values: R(0.3) diag(4, 0.25) R(-1.1) -> m = 4.
  auto rot = [](float a) {
    return glm::mat2(glm::vec2(std::cos(a), std::sin(a)), glm::vec2(-std::sin(a), std::cos(a)));
  };
  glm::mat2 J = rot(0.3f) * glm::mat2(glm::vec2(4, 0), glm::vec2(0, 0.25f)) * rot(-1.1f);
  CHECK(aliasingFactor(J) == doctest::Approx(4.0).epsilon(1e-5));
  // Shear [[1, k], [0, 1]]: sigma_min = (sqrt(k^2 + 4) - k) / 2; k = 1.5 gives 0.5, m = 2.
  glm::mat2 shear(glm::vec2(1, 0), glm::vec2(1.5f, 1));
  CHECK(smallestSingularValue(shear) == doctest::Approx(0.5).epsilon(1e-6));
  CHECK(aliasingFactor(shear) == doctest::Approx(2.0).epsilon(1e-6));
  // Magnified everywhere (2 texels per pixel both ways): alias-free, m = 1/2.
  CHECK(aliasingFactor(glm::mat2(2.0f)) == doctest::Approx(0.5));
  CHECK(std::isinf(aliasingFactor(glm::mat2(glm::vec2(1, 0), glm::vec2(2, 0)))));
}

TEST_CASE("measure.metrics: m of a projective texel mapping matches its closed form") {
  // Texel coordinates of screen pixel (x, y) through a projective map (a shadow map seen in
  // perspective): u = S x / (c y + 1), v = S y / (c y + 1). On the line x = 0 the Jacobian is
  // diag(S / (c y + 1), S / (c y + 1)^2), so m = (c y + 1)^2 / S there (for c y >= 0).
  const double S = 3.0, c = 0.05;
  auto texel = [&](double x, double y) { return glm::dvec2(S * x / (c * y + 1), S * y / (c * y + 1)); };
  for (double y : {0.0, 10.0, 30.0, 100.0}) {
    // Central differences, as the shader's derivatives would give at one pixel apart (h small here).
    const double h = 1e-3;
    glm::dvec2 dx = (texel(h, y) - texel(-h, y)) / (2 * h);
    glm::dvec2 dy = (texel(0, y + h) - texel(0, y - h)) / (2 * h);
    glm::mat2 J{glm::vec2(dx), glm::vec2(dy)};
    CAPTURE(y);
    CHECK(aliasingFactor(J) == doctest::Approx((c * y + 1) * (c * y + 1) / S).epsilon(1e-4));
  }
}

TEST_CASE("measure.metrics: aliasing statistics over m values and over J images") {
  // m = 0.1, 0.2, ..., 2.0 plus one background pixel.
  ImageF m;
  m.width = 21;
  m.height = 1;
  for (int k = 1; k <= 20; ++k) m.data.push_back(0.1f * k);
  m.data.push_back(NaN);
  AliasingStats s = aliasingStats(m);
  CHECK(s.pixels == 20);
  CHECK(s.mean == doctest::Approx(1.05).epsilon(1e-5));
  CHECK(s.rms == doctest::Approx(std::sqrt(2870.0 / 100.0 / 20.0)).epsilon(1e-5));
  CHECK(s.p95 == doctest::Approx(1.9).epsilon(1e-5));  // the 19th of 20
  CHECK(s.max == doctest::Approx(2.0).epsilon(1e-5));
  CHECK(s.shareAbove1 == doctest::Approx(0.5));  // 1.1 ... 2.0 (1.0 itself is alias-free)

  // A singular J is capped so the mean stays finite.
  ImageF inf = image(2, 1, {std::numeric_limits<float>::infinity(), 1.0f});
  AliasingStats capped = aliasingStats(inf, 8.0f);
  CHECK(capped.max == 8.0);
  CHECK(capped.mean == doctest::Approx(4.5));

  // 4-channel J = diag(0.25, 0.5) everywhere: m = 4; a NaN pixel is skipped.
  ImageF J = image(3, 1, {0.25f, 0, 0, 0.5f, 0.25f, 0, 0, 0.5f, NaN, NaN, NaN, NaN}, 4);
  AliasingStats sj = aliasingStats(J);
  CHECK(sj.pixels == 2);
  CHECK(sj.mean == doctest::Approx(4.0));
  CHECK(sj.p95 == doctest::Approx(4.0));
  CHECK(sj.shareAbove1 == 1.0);
  CHECK(std::isnan(aliasingFactors(J).data[2]));
}

TEST_CASE("measure.metrics: the m heatmap ramp separates alias-free from aliased pixels") {
  Rgb8 below = aliasingColor(0.5f), one = aliasingColor(1.0f), above = aliasingColor(1.5f);
  CHECK(below.g > below.r);
  CHECK(one.g > one.r);
  CHECK(above.r > above.b);
  CHECK(above.r >= above.g);
  // Redder as m grows beyond 1, saturating at maxM.
  CHECK(aliasingColor(2.0f).g > aliasingColor(8.0f).g);
  CHECK(aliasingColor(16.0f) == aliasingColor(1000.0f));
  // Brighter green as m approaches 1 from below.
  CHECK(aliasingColor(0.25f).g < aliasingColor(0.9f).g);
  std::vector<float> ticks = aliasingLegendTicks(16.0f);
  CHECK(ticks == std::vector<float>{1.0f / 16, 1.0f / 8, 0.25f, 0.5f, 1, 2, 4, 8, 16});
  Image8 heat = aliasingHeatmap(image(2, 1, {0.5f, NaN}));
  CHECK(heat.at(0, 0)[3] == 255);
  CHECK(heat.at(1, 0)[3] == 0);
  CHECK(Rgb8{heat.at(0, 0)[0], heat.at(0, 0)[1], heat.at(0, 0)[2]} == below);
}

namespace {

// A camera looking straight down on the ground (orthographic, pixels of 0.1 m, 16 x 8 of them) at
// x = cameraX: each pixel's ground point, and a technique's visibility from it. Top row first.
struct TopDown {
  static constexpr int kW = 16, kH = 8;
  static constexpr float kPixel = 0.1f;
  glm::mat4 viewProj{1.0f};
  ImageF position, reference, technique;
  template <class V>
  TopDown(float cameraX, V visibility) {
    const glm::mat4 view = glm::lookAt(glm::vec3(cameraX, 10, 0), glm::vec3(cameraX, 0, 0), glm::vec3(0, 0, -1));
    viewProj = glm::ortho(-kW * kPixel / 2, kW * kPixel / 2, -kH * kPixel / 2, kH * kPixel / 2, 1.0f, 20.0f) * view;
    const glm::mat4 toWorld = glm::inverse(viewProj);
    position = {kW, kH, 4, std::vector<float>(kW * kH * 4)};
    reference = {kW, kH, 1, std::vector<float>(kW * kH, 1.0f)};  // the ground is lit everywhere
    technique = {kW, kH, 1, std::vector<float>(kW * kH)};
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const glm::vec4 ndc((x + 0.5f) / kW * 2 - 1, 1 - (y + 0.5f) / kH * 2, 0.0f, 1.0f);  // row 0 on top
        glm::vec4 p = toWorld * ndc;
        p /= p.w;
        p.y = 0.0f;
        const std::size_t i = std::size_t(y * kW + x);
        for (int c = 0; c < 3; ++c) position.data[4 * i + std::size_t(c)] = p[c];
        technique.data[i] = visibility(glm::vec3(p), x);
      }
  }
  FrameSamples samples() const { return {&technique, &reference, &position, viewProj}; }
};

}  // namespace

TEST_CASE("measure.metrics: under a moving camera shimmer follows world points, not pixels") {
  // The camera moves one pixel (0.1 m) along x between the frames. A map whose wrong stripes stay
  // put in the world (snapped) flips no point; stripes that move with the camera (a fit that slides
  // with the view) flip a point at every stripe edge. Comparing pixel with pixel says the opposite.
  const auto fixedInWorld = [](const glm::vec3& p, int) { return std::fmod(std::floor(p.x / 0.4f + 100.0f), 2.0f); };
  const auto movingWithView = [](const glm::vec3&, int x) { return float((x / 4) % 2); };
  const TopDown a0(0.0f, fixedInWorld), a1(0.1f, fixedInWorld);
  const ReprojectedTemporalErrors world = compareFramesReprojected(a0.samples(), a1.samples());
  CHECK(world.errors.pixels == (TopDown::kW - 1) * TopDown::kH);
  CHECK(world.unmatched == TopDown::kH);  // the new column on the right: not seen before
  CHECK(world.errors.extraFlips == 0);
  CHECK(compareFrames(a0.technique, a1.technique, a0.reference, a1.reference).extraFlips > 0);

  const TopDown b0(0.0f, movingWithView), b1(0.1f, movingWithView);
  const ReprojectedTemporalErrors view = compareFramesReprojected(b0.samples(), b1.samples());
  CHECK(view.errors.extraFlips == 3 * TopDown::kH);  // the edges at columns 4, 8 and 12, a point each row
  CHECK(view.errors.extraFlipPct == doctest::Approx(100.0 * 3 / (TopDown::kW - 1)));
  CHECK(compareFrames(b0.technique, b1.technique, b0.reference, b1.reference).extraFlips == 0);

  // Points hidden in the previous frame (a box's top 3 m up covered columns 4-8 of rows 0-4 then)
  // are not compared: the new frame's columns 3-7 of those rows reproject there.
  TopDown c0(0.0f, fixedInWorld);
  for (int y = 0; y < 5; ++y)
    for (int x = 4; x < 9; ++x) c0.position.data[4 * std::size_t(y * TopDown::kW + x) + 1] = 3.0f;
  const ReprojectedTemporalErrors hidden = compareFramesReprojected(c0.samples(), a1.samples());
  CHECK(hidden.unmatched == TopDown::kH + 25);
  // Images that do not match are refused.
  FrameSamples broken = a1.samples();
  broken.position = &a1.reference;
  CHECK_THROWS_AS(compareFramesReprojected(a0.samples(), broken), std::invalid_argument);
}

// measure.metrics for soft shadows: the umbra over- and under-estimate next to the RMSE (lesson 05).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "measure/ground_truth.hpp"
#include "measure/metrics.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;

namespace {
ImageF row(std::vector<float> values) {
  ImageF img;
  img.width = int(values.size());
  img.height = 1;
  img.channels = 1;
  img.data = std::move(values);
  return img;
}
}  // namespace

TEST_CASE("measure.metrics: the umbra a soft technique over- and under-estimates") {
  // Pixels: agreed umbra, agreed lit, a hard shadow kept where the truth sees 30 % of the light
  // (over), a blurred umbra (under), a penumbra both see, and one not facing the light.
  const ImageF ref = row({0.0f, 1.0f, 0.3f, 0.0f, 0.5f, kNotFacing});
  const ImageF tech = row({0.01f, 1.0f, 0.0f, 0.2f, 0.45f, 0.0f});
  const SoftShadowErrors e = compareSoft(tech, ref);
  CHECK(e.pixels == 5);
  CHECK(e.umbraPixels == 2);  // pixels 0 and 3
  CHECK(e.umbraOver == 1);    // pixel 2
  CHECK(e.umbraUnder == 1);   // pixel 3
  CHECK(e.umbraOverPct == doctest::Approx(20.0));
  CHECK(e.umbraUnderPct == doctest::Approx(20.0));
  // The level is a parameter: at 0.25, pixel 3 (0.2) is umbra for both, and nothing is under.
  const SoftShadowErrors loose = compareSoft(tech, ref, 0.25f);
  CHECK(loose.umbraUnder == 0);
  CHECK(loose.umbraOver == 1);
  // A technique equal to the reference estimates nothing wrongly.
  const SoftShadowErrors same = compareSoft(ref, ref);
  CHECK(same.umbraOver == 0);
  CHECK(same.umbraUnder == 0);
  CHECK(same.rmse == 0.0);
}

TEST_CASE("measure.metrics: light bleeding is the reference's umbra brightened by more than 0.1") {
  // Umbra pixels: one bled into (0.3), one just under the level (0.09), one dark; a penumbra
  // pixel brightened by 0.4 is not bleeding (the reference sees part of the light there).
  const ImageF ref = row({0.0f, 0.0f, 0.0f, 0.5f, 1.0f});
  const ImageF tech = row({0.3f, 0.09f, 0.0f, 0.9f, 1.0f});
  const SoftShadowErrors e = compareSoft(tech, ref);
  CHECK(e.umbraPixels == 3);
  CHECK(e.bleed == 1);
  CHECK(e.bleedPct == doctest::Approx(100.0 / 3.0));
  CHECK(compareSoft(ref, ref).bleed == 0);
}

TEST_CASE("measure.metrics: shimmer is a flip between two frames that the reference does not make") {
  // Pixels: a still lit pixel, a true moving edge (both flip), a shimmering pixel (only the
  // technique flips), a pixel the reference flips and the technique misses, a soft pixel that
  // changes by 0.3 where the reference changes by 0.1, and one not facing the light before.
  const ImageF refBefore = row({1.0f, 1.0f, 1.0f, 0.0f, 0.6f, kNotFacing});
  const ImageF ref = row({1.0f, 0.0f, 1.0f, 1.0f, 0.7f, 1.0f});
  const ImageF techBefore = row({1.0f, 1.0f, 1.0f, 0.0f, 0.4f, 0.0f});
  const ImageF tech = row({1.0f, 0.0f, 0.0f, 0.0f, 0.7f, 1.0f});
  const TemporalErrors e = compareFrames(techBefore, tech, refBefore, ref);
  CHECK(e.pixels == 5);
  CHECK(e.flips == 3);  // the edge, the shimmer, and 0.4 -> 0.7 across the lit threshold
  CHECK(e.referenceFlips == 2);
  CHECK(e.extraFlips == 2);
  CHECK(e.extraFlipPct == doctest::Approx(40.0));
  CHECK(e.meanChange == doctest::Approx((1.0 + 1.0 + 0.3) / 5.0));
  CHECK(e.extraChange == doctest::Approx((1.0 + 0.2) / 5.0));  // the shimmer, and 0.3 - 0.1
  // Nothing moves: nothing shimmers.
  const TemporalErrors still = compareFrames(tech, tech, ref, ref);
  CHECK(still.flips == 0);
  CHECK(still.extraChange == 0.0);
}

TEST_CASE("measure.metrics: the shimmer overlay lights the pixels that flip where the reference does not") {
  // The same six pixels: the shimmering pixel (2) and 0.4 -> 0.7 across the lit threshold (4) are
  // the extra flips; the true edge (1), the missed flip (3) and the pixel not facing before (5) are not.
  const ImageF refBefore = row({1.0f, 1.0f, 1.0f, 0.0f, 0.6f, kNotFacing});
  const ImageF ref = row({1.0f, 0.0f, 1.0f, 1.0f, 0.7f, 1.0f});
  const ImageF techBefore = row({1.0f, 1.0f, 1.0f, 0.0f, 0.4f, 0.0f});
  const ImageF tech = row({1.0f, 0.0f, 0.0f, 0.0f, 0.7f, 1.0f});
  std::vector<std::uint8_t> at = {9, 9};  // replaced whole, whatever it held
  const TemporalErrors e = compareFrames(techBefore, tech, refBefore, ref, 0.5f, &at);
  CHECK(at == std::vector<std::uint8_t>{0, 0, 1, 0, 1, 0});
  CHECK(std::size_t(std::count(at.begin(), at.end(), 1)) == e.extraFlips);
  // Heat 1 is opaque yellow, a faded 0.5 half transparent, 0 leaves the picture alone.
  const Image8 overlay = shimmerHeatmap({1.0f, 0.5f, 0.0f}, 3, 1);
  CHECK(overlay.channels == 4);
  CHECK(overlay.data[0] == kShimmerColor.r);
  CHECK(overlay.data[1] == kShimmerColor.g);
  CHECK(overlay.data[2] == kShimmerColor.b);
  CHECK(overlay.data[3] == 255);
  CHECK(overlay.data[7] == 128);
  CHECK(overlay.data[11] == 0);
  CHECK_THROWS_WITH_AS(shimmerHeatmap({1.0f, 0.5f}, 3, 1), "shimmerHeatmap: 2 values for 3x1 pixels",
                       std::invalid_argument);
}

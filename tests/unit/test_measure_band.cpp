// measure/metrics: the band of pixels near a shadow edge (lesson 07's "within 2 texels of an
// edge"), on a synthetic view whose geometry gives the answer by counting columns.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "measure/metrics.hpp"

using namespace shadowlab;
using namespace shadowlab::measure;

namespace {

// A 20x10 view of the ground seen from above: pixel (x, y) is the world point (0.1 x, 0, 0.1 y);
// the left ten columns lit, the right ten shadowed, one background pixel in the corner.
struct View {
  ImageF reference, position;
  View() {
    reference.width = position.width = 20;
    reference.height = position.height = 10;
    reference.channels = 1;
    position.channels = 4;
    reference.data.assign(200, 0.0f);
    position.data.assign(800, 0.0f);
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 20; ++x) {
        reference.at(x, y) = x < 10 ? 1.0f : 0.0f;
        position.at(x, y, 0) = 0.1f * float(x);
        position.at(x, y, 2) = 0.1f * float(y);
        position.at(x, y, 3) = 1.0f;
      }
    reference.at(19, 9) = -2.0f;  // background: never in the band, never a boundary
  }
};

std::size_t count(const std::vector<std::uint8_t>& band) {
  std::size_t n = 0;
  for (auto b : band) n += b != 0;
  return n;
}

}  // namespace

TEST_CASE("edge band: a sun straight above measures across the light in the ground's plane") {
  View v;
  Light sun{LightKind::Directional};
  sun.direction = {0, -1, 0};
  // Boundary pixels: columns 9 and 10. Within 0.25 m of them: columns 7..12 (9 - 2 .. 10 + 2):
  // 6 columns of 10 rows, less the background pixel (column 19 is far anyway).
  const auto band = shadowEdgeBand(v.reference, v.position, sun, 0.25f);
  CHECK(count(band) == 60u);
  CHECK(band[5 * 20 + 7] == 1);
  CHECK(band[5 * 20 + 6] == 0);
  CHECK(band[5 * 20 + 12] == 1);
  CHECK(band[5 * 20 + 13] == 0);
  // Radius 0: only the boundary pixels themselves.
  CHECK(count(shadowEdgeBand(v.reference, v.position, sun, 0.0f)) == 20u);
}

TEST_CASE("edge band: distances along the light's ray do not count") {
  View v;
  // Light travelling along +x: across it only z (rows) separates points, so every facing pixel of
  // a row that holds boundary pixels within the window is in the band: all 199 facing pixels.
  Light grazing{LightKind::Directional};
  grazing.direction = {1, 0, 0};
  CHECK(count(shadowEdgeBand(v.reference, v.position, grazing, 0.01f)) == 199u);
  // A window too small to reach the boundary from the outer columns leaves them out: columns
  // 9 - 3 .. 10 + 3 are 8 columns, the background pixel is outside them.
  CHECK(count(shadowEdgeBand(v.reference, v.position, grazing, 0.01f, 3)) == 80u);
}

TEST_CASE("edge band: a spot light's radius is a width at unit distance") {
  View v;
  // A spot 10 m above the boundary: the ground 10 m away (a little more off-centre), so a width of
  // 0.025 at unit distance is about 0.25 m there, the sun's columns 7..12 again.
  Light spot{LightKind::Spot, {0.95f, 10.0f, 0.45f}};
  spot.direction = {0, -1, 0};
  const auto band = shadowEdgeBand(v.reference, v.position, spot, 0.025f);
  CHECK(count(band) == 60u);
}

TEST_CASE("edge band: keepWhere and bad sizes") {
  View v;
  std::vector<std::uint8_t> mask(200, 0);
  mask[3] = 1;
  const ImageF kept = keepWhere(v.position, mask);
  CHECK(kept.at(3, 0, 0) == doctest::Approx(0.3f));
  CHECK(std::isnan(kept.at(4, 0, 0)));
  CHECK(std::isnan(kept.at(4, 0, 3)));
  CHECK_THROWS_AS(keepWhere(v.position, std::vector<std::uint8_t>(10, 1)), std::invalid_argument);
  ImageF small = v.reference;
  small.width = 10;
  small.data.resize(100);
  CHECK_THROWS_AS(shadowEdgeBand(small, v.position, Light{}, 1.0f), std::invalid_argument);
}

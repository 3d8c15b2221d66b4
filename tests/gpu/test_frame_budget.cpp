// The frame budget's controller (common/app/frame_budget): the render scale that holds a frame
// rate on a software renderer. Pure arithmetic; the window itself is tested under Xvfb
// (tests/gpu/check_frame_budget.cmake).
#include <doctest/doctest.h>

#include "app/frame_budget.hpp"

using shadowlab::nextRenderScale;

TEST_CASE("frame budget: over budget, the scale drops at once to what the pixels allow") {
  // 4x over budget at full size: a quarter of the pixels, half the scale.
  CHECK(nextRenderScale(1.0f, 266.0, 66.5, 0.25f) == doctest::Approx(0.5f));
  // Far over budget: never below the floor.
  CHECK(nextRenderScale(1.0f, 5000.0, 66.5, 0.25f) == doctest::Approx(0.25f));
  // Steps of 0.05: 0.8 * sqrt(66.5 / 120) = 0.596 -> 0.55 (rounded down, under budget).
  CHECK(nextRenderScale(0.8f, 120.0, 66.5, 0.25f) == doctest::Approx(0.55f));
}

TEST_CASE("frame budget: under budget, it climbs back only when clearly under (no flicker)") {
  // Slightly under: stays.
  CHECK(nextRenderScale(0.6f, 60.0, 66.5, 0.25f) == doctest::Approx(0.6f));
  // Far under: 0.5 * sqrt(66.5 / 15) = 1.05 -> capped at 1.
  CHECK(nextRenderScale(0.5f, 15.0, 66.5, 0.25f) == doctest::Approx(1.0f));
  // Clearly under but not enough for full size: 0.5 * sqrt(66.5 / 30) = 0.744 -> 0.70.
  CHECK(nextRenderScale(0.5f, 30.0, 66.5, 0.25f) == doctest::Approx(0.70f));
  // No measurement yet, or nonsense: unchanged.
  CHECK(nextRenderScale(0.7f, 0.0, 66.5, 0.25f) == doctest::Approx(0.7f));
  CHECK(nextRenderScale(0.7f, 50.0, 0.0, 0.25f) == doctest::Approx(0.7f));
}

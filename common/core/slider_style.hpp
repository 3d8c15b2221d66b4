#pragma once
// How the parameter panel shows a number: three significant digits instead of three decimals (a
// bias of 0.0005 read "0.001" and a slope of 2e-5 read "0.000"), and a logarithmic slider where the
// range spans decades or sits far below 1, so the small values a lecturer tunes get the travel.
namespace shadowlab {

struct SliderStyle {
  const char* format;  // printf format for the value
  bool logarithmic;
};

constexpr SliderStyle sliderStyle(float min, float max) {
  const bool decades = min > 0.0f && max >= 100.0f * min;
  const bool small = min == 0.0f && max > 0.0f && max <= 0.1f;
  return {"%.3g", decades || small};
}

}  // namespace shadowlab

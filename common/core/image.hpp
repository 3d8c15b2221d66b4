#pragma once
// Images on the CPU: 8-bit for files and screenshots, float for measurements. Row 0 is the TOP row
// (as in PNG files); GL read-backs are flipped on the way in (common/gl).
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

struct Image8 {
  int width = 0, height = 0, channels = 4;
  std::vector<std::uint8_t> data;  // width * height * channels, row-major, top row first
  std::uint8_t* at(int x, int y) { return &data[(std::size_t(y) * width + x) * channels]; }
  const std::uint8_t* at(int x, int y) const { return &data[(std::size_t(y) * width + x) * channels]; }
};

struct ImageF {
  int width = 0, height = 0, channels = 1;
  std::vector<float> data;
  float& at(int x, int y, int c = 0) { return data[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c = 0) const { return data[(std::size_t(y) * width + x) * channels + c]; }
};

// PNG/JPEG/... through stb_image. Throws std::runtime_error naming the path and the reason.
Image8 loadImage(const std::string& path, int desiredChannels = 4);
// PNG through stb_image_write. Throws std::runtime_error naming the path on failure.
void savePng(const std::string& path, const Image8& image);

struct ImageDiff {
  double rmse = 0;                  // over all channels, in [0,255] units
  int maxAbs = 0;                   // largest channel difference
  std::size_t differingPixels = 0;  // pixels with any channel differing by more than the tolerance
};
// Throws std::invalid_argument when sizes or channel counts differ (naming both).
ImageDiff compareImages(const Image8& a, const Image8& b, int tolerance = 0);
// |a - b| per channel, scaled by `gain` and clamped, alpha forced opaque.
Image8 diffImage(const Image8& a, const Image8& b, float gain = 4.0f);
// True when every pixel equals the first one (a blank render).
bool isUniform(const Image8& image);

}  // namespace shadowlab

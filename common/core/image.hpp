#pragma once
// Images on the CPU: 8-bit for files and screenshots, float for measurements. Row 0 is the TOP row
// (as in PNG files); GL read-backs are flipped on the way in (common/gl).
#include <cstddef>
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

// Images the course reads are PNG (textures, screenshots, golden images) and nothing else: the
// signature is checked before anything is decoded, so a JPEG, TGA or PIC named .png is refused
// instead of being decoded by a format guess. Bounds checked before decoding (from the header):
inline constexpr int kMaxImageSide = 16384;                           // pixels, a side
inline constexpr std::size_t kMaxImagePixels = std::size_t(1) << 26;  // 64 Mpixels: 256 MiB as RGBA

// PNG through libspng (a decoder written for untrusted input): every chunk's CRC and the zlib
// Adler-32 are verified, a 0-sized or truncated image is an error. `desiredChannels` 1 to 4
// converts (1: luma, 2: luma + alpha, 3: RGB, 4: RGBA, opaque where the file has no alpha); 0
// keeps the file's own (a palette or tRNS counts as alpha). Throws std::runtime_error
// "cannot load image 'PATH': reason".
Image8 loadImage(const std::string& path, int desiredChannels = 4);
// The same on bytes in memory; `name` is what the message calls them.
Image8 decodePng(const std::uint8_t* bytes, std::size_t size, int desiredChannels, const std::string& name);
// PNG through stb_image_write. Throws std::runtime_error naming the path and the reason on any
// failure, including a full disk (--screenshot /dev/full).
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

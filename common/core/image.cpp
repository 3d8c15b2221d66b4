// The only translation unit that compiles stb_image and stb_image_write.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "core/image.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace shadowlab {

namespace {
std::string describe(const Image8& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

void requireConsistent(const Image8& image, const char* what) {
  if (image.width < 0 || image.height < 0 || image.channels < 1 || image.channels > 4 ||
      image.data.size() != std::size_t(image.width) * image.height * image.channels)
    throw std::invalid_argument(std::string(what) + ": image " + describe(image) + " holds " +
                                std::to_string(image.data.size()) + " bytes");
}

void requireSameShape(const Image8& a, const Image8& b, const char* what) {
  requireConsistent(a, what);
  requireConsistent(b, what);
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument(std::string(what) + ": images differ in shape, " + describe(a) + " vs " + describe(b));
}
}  // namespace

Image8 loadImage(const std::string& path, int desiredChannels) {
  if (desiredChannels < 0 || desiredChannels > 4)
    throw std::invalid_argument("loadImage('" + path + "'): desiredChannels must be 0..4, got " +
                                std::to_string(desiredChannels));
  int w = 0, h = 0, fileChannels = 0;
  errno = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &w, &h, &fileChannels, desiredChannels),
                                                   stbi_image_free);
  if (!pixels) {
    // stb says "can't fopen" for a missing file; errno says why the open failed.
    std::string reason = stbi_failure_reason() ? stbi_failure_reason() : "unknown error";
    if (errno != 0 && reason == "can't fopen") reason += std::string(" (") + std::strerror(errno) + ")";
    throw std::runtime_error("cannot load image '" + path + "': " + reason);
  }
  Image8 image;
  image.width = w;
  image.height = h;
  image.channels = desiredChannels != 0 ? desiredChannels : fileChannels;
  image.data.assign(pixels.get(), pixels.get() + std::size_t(w) * h * image.channels);
  return image;
}

void savePng(const std::string& path, const Image8& image) {
  requireConsistent(image, ("savePng('" + path + "')").c_str());
  if (image.width == 0 || image.height == 0)
    throw std::invalid_argument("savePng('" + path + "'): image is empty (" + describe(image) + ")");
  errno = 0;
  const int ok = stbi_write_png(path.c_str(), image.width, image.height, image.channels, image.data.data(),
                                image.width * image.channels);
  if (!ok) {
    const std::string reason = errno != 0 ? std::strerror(errno) : "stb_image_write failed";
    throw std::runtime_error("cannot write PNG '" + path + "': " + reason);
  }
}

ImageDiff compareImages(const Image8& a, const Image8& b, int tolerance) {
  requireSameShape(a, b, "compareImages");
  ImageDiff diff;
  double sumSquares = 0.0;
  const std::size_t pixels = std::size_t(a.width) * a.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < a.channels; ++c) {
      const std::size_t i = p * a.channels + c;
      const int d = std::abs(int(a.data[i]) - int(b.data[i]));
      sumSquares += double(d) * d;
      worst = std::max(worst, d);
    }
    diff.maxAbs = std::max(diff.maxAbs, worst);
    if (worst > tolerance) ++diff.differingPixels;
  }
  if (!a.data.empty()) diff.rmse = std::sqrt(sumSquares / double(a.data.size()));
  return diff;
}

// The result is always RGBA so any viewer shows it; grey inputs (1-2 channels) are replicated.
Image8 diffImage(const Image8& a, const Image8& b, float gain) {
  requireSameShape(a, b, "diffImage");
  Image8 out;
  out.width = a.width;
  out.height = a.height;
  out.channels = 4;
  out.data.assign(std::size_t(a.width) * a.height * 4, 255);
  const int colorChannels = a.channels >= 3 ? 3 : 1;
  const std::size_t pixels = std::size_t(a.width) * a.height;
  for (std::size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = p * a.channels + std::min(c, colorChannels - 1);
      const float d = std::fabs(float(a.data[i]) - float(b.data[i])) * gain;
      // NaN or negative gains read as no difference; casting them would be undefined.
      const float v = d > 0.0f ? std::min(d, 255.0f) : 0.0f;
      out.data[p * 4 + c] = static_cast<std::uint8_t>(v + 0.5f);
    }
  return out;
}

bool isUniform(const Image8& image) {
  const std::size_t stride = std::size_t(std::max(image.channels, 1));
  if (image.data.size() < stride) return true;  // no pixels: nothing differs
  for (std::size_t i = stride; i + stride <= image.data.size(); i += stride)
    if (!std::equal(image.data.begin(), image.data.begin() + stride, image.data.begin() + i)) return false;
  return true;
}

}  // namespace shadowlab

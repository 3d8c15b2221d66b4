// Reading PNG through libspng, writing it through stb_image_write (the only translation unit
// that compiles it). stb_image is not used for reading: it guesses the format from the content
// and its PIC, JPEG and TGA decoders crashed or allocated gigabytes on fuzzed files.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <spng.h>
#include <stb_image_write.h>

#include "core/image.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
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

namespace {
constexpr std::uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct PngFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the first bytes say the file is, for the message when it is not a PNG.
std::string guessFormat(const std::uint8_t* b, std::size_t n) {
  auto starts = [&](const char* magic) {
    const std::size_t m = std::strlen(magic);
    return n >= m && std::memcmp(b, magic, m) == 0;
  };
  if (n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff) return "a JPEG";
  if (starts("GIF8")) return "a GIF";
  if (starts("BM")) return "a BMP";
  if (n >= 4 && std::memcmp(b, "\x53\x80\xf6\x34", 4) == 0) return "a PIC";
  if (n >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7') return "a PNM";
  if (starts("8BPS")) return "a PSD";
  if (starts("#?RADIANCE") || starts("#?RGBE")) return "an HDR";
  return "not a PNG";
}

void require(int error, const char* what) {
  if (error != 0) throw PngFailure(std::string(what) + ": " + spng_strerror(error));
}

// The file's channel count as decodePng(..., 0) reports it.
int fileChannels(const spng_ihdr& ihdr, bool hasTrns) {
  switch (ihdr.color_type) {
    case SPNG_COLOR_TYPE_GRAYSCALE: return hasTrns ? 2 : 1;
    case SPNG_COLOR_TYPE_GRAYSCALE_ALPHA: return 2;
    case SPNG_COLOR_TYPE_TRUECOLOR: return hasTrns ? 4 : 3;
    case SPNG_COLOR_TYPE_INDEXED: return hasTrns ? 4 : 3;
    default: return 4;
  }
}

// RGBA8 to 1-4 channels; luma as stb_image computed it (77 R + 150 G + 29 B) / 256, exact for grey.
Image8 convert(const std::vector<std::uint8_t>& rgba, int w, int h, int channels) {
  Image8 out;
  out.width = w;
  out.height = h;
  out.channels = channels;
  const std::size_t pixels = std::size_t(w) * std::size_t(h);
  out.data.resize(pixels * std::size_t(channels));
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* in = &rgba[p * 4];
    std::uint8_t* o = &out.data[p * std::size_t(channels)];
    const auto luma = std::uint8_t((77u * in[0] + 150u * in[1] + 29u * in[2]) >> 8);
    switch (channels) {
      case 1: o[0] = luma; break;
      case 2: o[0] = luma, o[1] = in[3]; break;
      default: std::memcpy(o, in, std::size_t(channels));
    }
  }
  return out;
}

Image8 decode(const std::uint8_t* bytes, std::size_t size, int desiredChannels) {
  if (size < sizeof kPngSignature || std::memcmp(bytes, kPngSignature, sizeof kPngSignature) != 0)
    throw PngFailure(guessFormat(bytes, size) + " file (" + std::to_string(size) +
                     " bytes); the course reads PNG only (convert it to PNG)");
  std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(0), spng_ctx_free);
  if (!ctx) throw PngFailure("out of memory");
  require(spng_set_crc_action(ctx.get(), SPNG_CRC_ERROR, SPNG_CRC_ERROR), "checksums");
  require(spng_set_image_limits(ctx.get(), kMaxImageSide, kMaxImageSide), "limits");
  require(spng_set_chunk_limits(ctx.get(), std::size_t(1) << 26, std::size_t(1) << 26), "limits");
  require(spng_set_png_buffer(ctx.get(), bytes, size), "buffer");
  spng_ihdr ihdr{};
  require(spng_get_ihdr(ctx.get(), &ihdr), "header");
  if (ihdr.width == 0 || ihdr.height == 0) throw PngFailure("the image is empty (0 pixels)");
  if (std::size_t(ihdr.width) * ihdr.height > kMaxImagePixels)
    throw PngFailure(std::to_string(ihdr.width) + "x" + std::to_string(ihdr.height) + " is over the limit of " +
                     std::to_string(kMaxImagePixels >> 20) + " Mpixels");
  spng_trns trns{};
  const bool hasTrns = spng_get_trns(ctx.get(), &trns) == 0;
  std::size_t bytesOut = 0;
  require(spng_decoded_image_size(ctx.get(), SPNG_FMT_RGBA8, &bytesOut), "size");
  if (bytesOut != std::size_t(ihdr.width) * ihdr.height * 4) throw PngFailure("unexpected decoded size");
  std::vector<std::uint8_t> rgba(bytesOut);
  require(spng_decode_image(ctx.get(), rgba.data(), rgba.size(), SPNG_FMT_RGBA8, SPNG_DECODE_TRNS), "pixels");
  // The rest up to IEND: the last IDAT's CRC is read only here.
  require(spng_decode_chunks(ctx.get()), "after the pixels");
  const int channels = desiredChannels != 0 ? desiredChannels : fileChannels(ihdr, hasTrns);
  return convert(rgba, int(ihdr.width), int(ihdr.height), channels);
}

std::string loadError(const std::string& name, const std::string& why) {
  return "cannot load image '" + name + "': " + why;
}
}  // namespace

Image8 decodePng(const std::uint8_t* bytes, std::size_t size, int desiredChannels, const std::string& name) {
  if (desiredChannels < 0 || desiredChannels > 4)
    throw std::invalid_argument("loadImage('" + name + "'): desiredChannels must be 0..4, got " +
                                std::to_string(desiredChannels));
  try {
    return decode(bytes, size, desiredChannels);
  } catch (const PngFailure& e) { throw std::runtime_error(loadError(name, e.what())); }
}

Image8 loadImage(const std::string& path, int desiredChannels) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error(loadError(path, "not a regular file"));
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(loadError(path, std::strerror(errno)));
  const std::streamoff size = in.tellg();
  // A PNG of the largest allowed image compresses to far less than this; bigger is not one.
  if (size < 0 || std::uint64_t(size) > kMaxImagePixels * 8)
    throw std::runtime_error(loadError(path, "not a regular file of a plausible size"));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) throw std::runtime_error(loadError(path, "read error"));
  return decodePng(bytes.data(), bytes.size(), desiredChannels, path);
}

void savePng(const std::string& path, const Image8& image) {
  requireConsistent(image, ("savePng('" + path + "')").c_str());
  if (image.width == 0 || image.height == 0)
    throw std::invalid_argument("savePng('" + path + "'): image is empty (" + describe(image) + ")");
  int length = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> png(
      stbi_write_png_to_mem(image.data.data(), image.width * image.channels, image.width, image.height, image.channels,
                            &length),
      std::free);
  if (!png) throw std::runtime_error("cannot write PNG '" + path + "': encoding failed");
  // stbi_write_png ignores fwrite's and fclose's results: a full disk wrote nothing and said ok.
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write PNG '" + path + "': " + std::strerror(errno));
  const bool written = std::fwrite(png.get(), 1, std::size_t(length), f) == std::size_t(length);
  const int writeErrno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed)
    throw std::runtime_error("cannot write PNG '" + path + "': " + std::strerror(written ? errno : writeErrno));
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

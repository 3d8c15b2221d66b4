// Images: PNG round trips, comparisons with RMSE worked out by hand, diff images, and errors that
// name the file.
#include <doctest/doctest.h>

#include <initializer_list>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/image.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {
Image8 filled(int w, int h, int channels, std::uint8_t value) {
  Image8 image;
  image.width = w;
  image.height = h;
  image.channels = channels;
  image.data.assign(std::size_t(w) * h * channels, value);
  return image;
}
std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }
}  // namespace

TEST_CASE("image: PNG round trip keeps every byte, for 1 to 4 channels") {
  for (int channels = 1; channels <= 4; ++channels) {
    INFO(channels);
    Image8 image = filled(7, 5, channels, 0);
    for (std::size_t i = 0; i < image.data.size(); ++i) image.data[i] = std::uint8_t(i * 37 + 11);
    const std::string path = temp("shadowlab_roundtrip_" + std::to_string(channels) + ".png");
    savePng(path, image);
    const Image8 back = loadImage(path, channels);
    std::filesystem::remove(path);
    CHECK(back.width == 7);
    CHECK(back.height == 5);
    CHECK(back.channels == channels);
    CHECK(back.data == image.data);
  }
  // Row 0 is the top row in the file, too: a red top row comes back first.
  Image8 rows = filled(2, 2, 3, 0);
  rows.at(0, 0)[0] = rows.at(1, 0)[0] = 255;
  const std::string path = temp("shadowlab_rows.png");
  savePng(path, rows);
  const Image8 back = loadImage(path);  // default: 4 channels, alpha added opaque
  std::filesystem::remove(path);
  CHECK(back.channels == 4);
  CHECK(back.at(1, 0)[0] == 255);
  CHECK(back.at(0, 1)[0] == 0);
  CHECK(back.at(0, 1)[3] == 255);
}

TEST_CASE("image: compare on synthetic pairs with known RMSE") {
  const Image8 a = filled(4, 4, 3, 100);
  Image8 b = a;
  CHECK(compareImages(a, b).rmse == 0.0);
  CHECK(compareImages(a, b).differingPixels == 0);
  // Every channel off by 10: RMSE is exactly 10.
  b = filled(4, 4, 3, 110);
  ImageDiff d = compareImages(a, b);
  CHECK(d.rmse == doctest::Approx(10.0));
  CHECK(d.maxAbs == 10);
  CHECK(d.differingPixels == 16);
  CHECK(compareImages(a, b, 10).differingPixels == 0);  // within tolerance
  // One channel of one pixel off by 48 among 48 values: sqrt(48^2 / 48) = sqrt(48).
  b = a;
  b.at(2, 3)[1] = 148;
  d = compareImages(a, b, 5);
  CHECK(d.rmse == doctest::Approx(std::sqrt(48.0)));
  CHECK(d.maxAbs == 48);
  CHECK(d.differingPixels == 1);
  // Symmetric.
  CHECK(compareImages(b, a).rmse == d.rmse);
}

TEST_CASE("image: shape mismatches are invalid arguments naming both shapes") {
  try {
    compareImages(filled(4, 4, 3, 0), filled(4, 2, 3, 0));
    FAIL("expected invalid_argument");
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    CHECK(m.find("4x4x3") != std::string::npos);
    CHECK(m.find("4x2x3") != std::string::npos);
  }
  CHECK_THROWS_AS(compareImages(filled(4, 4, 3, 0), filled(4, 4, 4, 0)), std::invalid_argument);
  CHECK_THROWS_AS(diffImage(filled(4, 4, 3, 0), filled(5, 4, 3, 0)), std::invalid_argument);
  Image8 broken = filled(4, 4, 3, 0);
  broken.data.pop_back();
  CHECK_THROWS_AS(compareImages(broken, broken), std::invalid_argument);
}

TEST_CASE("image: diff image scales the difference, clamps, and is opaque") {
  Image8 a = filled(2, 1, 3, 50), b = filled(2, 1, 3, 50);
  b.at(0, 0)[0] = 60;   // +10 -> 40 at gain 4
  b.at(1, 0)[2] = 250;  // +200 -> 800, clamped to 255
  const Image8 d = diffImage(a, b, 4.0f);
  REQUIRE(d.channels == 4);
  CHECK(d.at(0, 0)[0] == 40);
  CHECK(d.at(0, 0)[1] == 0);
  CHECK(d.at(1, 0)[2] == 255);
  CHECK(d.at(0, 0)[3] == 255);
  CHECK(d.at(1, 0)[3] == 255);
  // Grey inputs come out grey.
  Image8 g1 = filled(1, 1, 1, 10), g2 = filled(1, 1, 1, 13);
  const Image8 dg = diffImage(g1, g2, 2.0f);
  CHECK(dg.at(0, 0)[0] == 6);
  CHECK(dg.at(0, 0)[1] == 6);
  CHECK(dg.at(0, 0)[2] == 6);
}

TEST_CASE("image: uniform detection finds a single differing pixel") {
  Image8 image = filled(16, 16, 4, 7);
  CHECK(isUniform(image));
  image.at(15, 15)[2] = 8;
  CHECK_FALSE(isUniform(image));
  image = filled(16, 16, 4, 7);
  image.at(3, 0)[3] = 0;  // alpha counts too
  CHECK_FALSE(isUniform(image));
}

TEST_CASE("image: load and save errors name the path and the reason") {
  const std::string missing = temp("shadowlab_no_such_image.png");
  try {
    loadImage(missing);
    FAIL("expected runtime_error");
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    CHECK(m.find(missing) != std::string::npos);
    CHECK(m.find("No such file or directory") != std::string::npos);  // errno's reason
  }
  const std::string garbage = temp("shadowlab_garbage.png");
  {
    FILE* f = std::fopen(garbage.c_str(), "wb");
    REQUIRE(f);
    std::fputs("this is not an image", f);
    std::fclose(f);
  }
  try {
    loadImage(garbage);
    FAIL("expected runtime_error");
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    CHECK(m.find(garbage) != std::string::npos);
    CHECK(m.find("not a PNG file (20 bytes); the course reads PNG only (convert it to PNG)") != std::string::npos);
  }
  std::filesystem::remove(garbage);
  const std::string unwritable = temp("shadowlab_no_such_dir/out.png");
  try {
    savePng(unwritable, filled(2, 2, 3, 0));
    FAIL("expected runtime_error");
  } catch (const std::runtime_error& e) { CHECK(std::string(e.what()).find(unwritable) != std::string::npos); }
  CHECK_THROWS_AS(savePng(temp("shadowlab_empty.png"), Image8{}), std::invalid_argument);
}

TEST_CASE("image: the fuzzing finds are refused with one line naming the file and the reason") {
  // tests/fuzz/image/regressions: each crashed, misread or exhausted memory through stb_image 2.27
  // (which guessed the format from the content), or is a PNG that must not load.
  const std::string dir = test::sourceTree() + "/tests/fuzz/image/regressions/";
  const std::pair<const char*, const char*> cases[] = {
      {"pic_truncated_segv.png",
       "a PIC file (111 bytes); the course reads PNG only (convert it to PNG)"},  // segfaulted
      {"jpeg_bad_huffman_counts.png",
       "a JPEG file (41 bytes); the course reads PNG only (convert it to PNG)"},  // UBSan: index 257
      {"tga_52_bytes_727mb.png",
       "not a PNG file (52 bytes); the course reads PNG only (convert it to PNG)"},             // 13648x13322 zeros
      {"pnm_0x0.png", "a PNM file (11 bytes); the course reads PNG only (convert it to PNG)"},  // a 0x0 image
      {"png_0x0.png", "header: invalid image width"},                                           // 0-sized
      {"png_huge_header.png", "header: image width exceeds user limit"},                        // 100000 a side
      {"png_over_pixel_budget.png", "16384x8193 is over the limit of 64 Mpixels"},              // before decoding
      {"png_bad_crc.png", "after the pixels: invalid chunk checksum"},                          // CRC verified
      {"png_truncated.png", "pixels: end of stream"},
  };
  for (const auto& [file, reason] : cases)
    for (int channels = 0; channels <= 4; ++channels) {
      const std::string& shown = file;  // INFO captures in a lambda: not a structured binding (clang 14)
      INFO(shown << " with " << channels << " channels");
      try {
        loadImage(dir + file, channels);
        FAIL("loaded");
      } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()) == "cannot load image '" + dir + file + "': " + reason);
      }
    }
}

TEST_CASE("image: every PNG colour type and depth decodes, converted to the channels asked for") {
  const std::string dir = test::sourceTree() + "/tests/fuzz/image/seeds/";
  const std::pair<const char*, int> files[] = {
      {"grey1.png", 1}, {"grey8.png", 1},  {"grey16.png", 1},       {"grey_alpha.png", 2},   {"rgb8.png", 3},
      {"rgba8.png", 4}, {"rgba16.png", 4}, {"palette_trns.png", 4}, {"rgb_trns_text.png", 4}};
  for (const auto& [file, own] : files) {
    const char* shown = file;  // INFO captures in a lambda: not a structured binding (clang 14)
    INFO(shown);
    CHECK(loadImage(dir + file, 0).channels == own);
    const Image8 rgba = loadImage(dir + file, 4);
    for (int channels = 1; channels <= 3; ++channels) {
      const Image8 fewer = loadImage(dir + file, channels);
      REQUIRE(fewer.data.size() == std::size_t(rgba.width) * rgba.height * channels);
      if (channels == 3) CHECK(fewer.at(1, 1)[2] == rgba.at(1, 1)[2]);
      if (channels == 2) CHECK(fewer.at(1, 1)[1] == rgba.at(1, 1)[3]);  // alpha kept
    }
  }
  // The palette's second entry is green at alpha 128 (tRNS), the third blue and opaque.
  const Image8 palette = loadImage(dir + std::string("palette_trns.png"), 4);
  CHECK(palette.at(1, 0)[1] == 255);
  CHECK(palette.at(1, 0)[3] == 128);
  CHECK(palette.at(2, 0)[3] == 0);
}

TEST_CASE("image: a write error is an error (a full disk, a directory)") {
  try {
    savePng("/dev/full", filled(4, 4, 3, 7));
    FAIL("wrote to /dev/full");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "cannot write PNG '/dev/full': No space left on device");
  }
  try {
    loadImage(std::filesystem::temp_directory_path().string());
    FAIL("loaded a directory");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("not a regular file") != std::string::npos);
  }
}

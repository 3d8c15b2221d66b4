// Images: PNG round trips, comparisons with RMSE worked out by hand, diff images, and errors that
// name the file.
#include <doctest/doctest.h>

#include <initializer_list>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/image.hpp"

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
    CHECK(m.find("fopen") != std::string::npos);  // stb's reason
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
    CHECK(m.find("unknown image type") != std::string::npos);  // stb's reason
  }
  std::filesystem::remove(garbage);
  const std::string unwritable = temp("shadowlab_no_such_dir/out.png");
  try {
    savePng(unwritable, filled(2, 2, 3, 0));
    FAIL("expected runtime_error");
  } catch (const std::runtime_error& e) { CHECK(std::string(e.what()).find(unwritable) != std::string::npos); }
  CHECK_THROWS_AS(savePng(temp("shadowlab_empty.png"), Image8{}), std::invalid_argument);
}

// Image files (core/image): a PNG decoded within the bounds, or std::runtime_error. The number
// of channels asked for comes from the input's length, so the bytes themselves stay a file.
#include <stdexcept>

#include "core/image.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const int channels = int(size % 5);
  try {
    const Image8 image = decodePng(data, size, channels, "fuzz.png");
    FUZZ_CHECK(image.width > 0 && image.height > 0);
    FUZZ_CHECK(image.width <= kMaxImageSide && image.height <= kMaxImageSide);
    FUZZ_CHECK(std::size_t(image.width) * image.height <= kMaxImagePixels);
    FUZZ_CHECK(image.channels >= 1 && image.channels <= 4 && (channels == 0 || image.channels == channels));
    FUZZ_CHECK(image.data.size() == std::size_t(image.width) * image.height * image.channels);
  } catch (const std::runtime_error&) {}
  return 0;
}

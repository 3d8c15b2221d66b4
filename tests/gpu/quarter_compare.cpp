// One quarter of lesson 10's four-up view against the same technique drawn alone at the quarter's
// size: the four-up view must show each technique's own picture, not a neighbour's maps or a
// stale light camera.
//   quarter_compare FOUR_UP.png Q ALONE.png
// Q: 0 top left, 1 top right, 2 bottom left, 3 bottom right (the order of quarter.0..3). Passes
// within the golden images' tolerance (at most 0.2 % of the pixels with a channel more than 2
// levels off, an RMSE of at most 1 level); prints the difference either way, writes
// ALONE_quarter_diff.png (x8) when it fails. Exit 0 same, 1 different, 2 bad arguments or files.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "core/image.hpp"

using namespace shadowlab;

namespace {

// The w x h block of `image` at (x0, y0), top row first like the image.
Image8 crop(const Image8& image, int x0, int y0, int w, int h) {
  Image8 out;
  out.width = w;
  out.height = h;
  out.channels = image.channels;
  out.data.resize(std::size_t(w) * h * image.channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < image.channels; ++c) out.at(x, y)[c] = image.at(x0 + x, y0 + y)[c];
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: quarter_compare FOUR_UP.png Q ALONE.png (Q: 0 top left, 1 top right, 2 bottom left, "
                 "3 bottom right)\n";
    return 2;
  }
  const std::string q = argv[2];
  if (q.size() != 1 || q[0] < '0' || q[0] > '3') {
    std::cerr << "quarter_compare: quarter '" << q << "' is not one of 0, 1, 2, 3\n";
    return 2;
  }
  try {
    const Image8 four = loadImage(argv[1], 3), alone = loadImage(argv[3], 3);
    const int w = four.width / 2, h = four.height / 2, n = q[0] - '0';
    if (alone.width != w || alone.height != h) {
      std::cerr << "quarter_compare: " << argv[3] << " is " << alone.width << "x" << alone.height << ", a quarter of "
                << argv[1] << " is " << w << "x" << h << '\n';
      return 2;
    }
    const Image8 part = crop(four, (n % 2) * w, (n / 2) * h, w, h);
    const ImageDiff d = compareImages(part, alone, 2);
    const double share = 100.0 * double(d.differingPixels) / double(std::size_t(w) * h);
    const bool same = share <= 0.2 && d.rmse <= 1.0;
    std::cout << (same ? "same: " : "DIFFERENT: ") << "quarter " << n << " of " << argv[1] << " against " << argv[3]
              << ": worst channel difference " << d.maxAbs << ", " << d.differingPixels << " pixels (" << share
              << " %) off by more than 2, RMSE " << d.rmse << '\n';
    if (!same) {
      std::string diff = argv[3];
      diff = diff.substr(0, diff.size() - 4) + "_quarter_diff.png";
      savePng(diff, diffImage(part, alone, 8.0f));
      std::cout << "difference x8: " << diff << '\n';
    }
    return same ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "quarter_compare: " << e.what() << '\n';
    return 2;
  }
}

// The ground-truth overlay shows the values it claims: a screenshot with measure.overlay=reference
// (opacity 1) against the visibility image --measure writes beside its JSON (FILE_reference.png).
//   overlay_compare SHOT.png REFERENCE.png
// Over the reference's opaque pixels (the scene; the background is transparent there), at most
// 0.5 % may differ by more than 2 levels in a channel, and at least 0.5 % must be mid-grey (30 to
// 225: a penumbra), so that an overlay decoded twice as sRGB (0.53 shown as 63, not 136) fails and
// a picture of pure black and white cannot pass by luck. Exit 0 same, 1 different, 2 bad arguments.
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "core/image.hpp"

using namespace shadowlab;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: overlay_compare SHOT.png REFERENCE.png\n";
    return 2;
  }
  try {
    const Image8 shot = loadImage(argv[1]), ref = loadImage(argv[2]);
    if (shot.width != ref.width || shot.height != ref.height || ref.channels != 4 || shot.channels != 4) {
      std::cerr << "overlay_compare: " << shot.width << "x" << shot.height << "x" << shot.channels << " against "
                << ref.width << "x" << ref.height << "x" << ref.channels << " (want the same size, RGBA reference)\n";
      return 2;
    }
    long compared = 0, off = 0, mid = 0, worst = 0;
    for (int y = 0; y < ref.height; ++y)
      for (int x = 0; x < ref.width; ++x) {
        const std::uint8_t* r = ref.at(x, y);
        if (r[3] != 255) continue;
        ++compared;
        const std::uint8_t* s = shot.at(x, y);
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(s[c]) - int(r[c])));
        worst = std::max<long>(worst, d);
        off += d > 2;
        mid += r[0] >= 30 && r[0] <= 225;
      }
    const double offPct = compared ? 100.0 * double(off) / double(compared) : 100.0;
    const double midPct = compared ? 100.0 * double(mid) / double(compared) : 0.0;
    std::cout << "overlay_compare: " << compared << " scene pixels, " << offPct << " % more than 2 levels off (worst "
              << worst << "), " << midPct << " % mid-grey in the reference\n";
    if (midPct < 0.5) {
      std::cerr << "overlay_compare: the reference has too few mid-grey pixels to tell a wrong decode\n";
      return 1;
    }
    return offPct <= 0.5 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "overlay_compare: " << e.what() << '\n';
    return 2;
  }
}

#include "app/frame_loop.hpp"

namespace shadowlab {

int runFrames(FrameStep step) {
  for (int frame = 0;; ++frame)
    if (std::optional<int> exit = step(frame)) return *exit;
}

void exposeParams(const ParamRegistry*) {}

}  // namespace shadowlab

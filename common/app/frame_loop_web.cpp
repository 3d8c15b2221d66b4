// The browser's frame loop: the page calls one step per animation frame (requestAnimationFrame,
// through emscripten_set_main_loop_arg); main returns at once and the runtime stays alive.
#include <emscripten.h>

#include <exception>
#include <iostream>
#include <memory>

#include "app/frame_loop.hpp"

namespace shadowlab {
namespace {

struct Loop {
  FrameStep step;
  int frame = 0;
};

void finish(Loop* loop, int code) {
  emscripten_cancel_main_loop();
  delete loop;
  EM_ASM(
      {
        if (Module.onLessonExit) Module.onLessonExit($0);
      },
      code);
}

void tick(void* arg) {
  auto* loop = static_cast<Loop*>(arg);
  std::optional<int> exit;
  try {
    exit = loop->step(loop->frame++);
  } catch (const std::exception& e) {  // the lesson's own code reports and exits; this is a last resort
    std::cerr << "shadowlab: the frame loop stopped: " << e.what() << '\n';
    exit = 1;
  }
  if (exit) finish(loop, *exit);
}

}  // namespace

int runFrames(FrameStep step) {
  emscripten_set_main_loop_arg(tick, new Loop{std::move(step)}, 0, false);
  return 0;
}

}  // namespace shadowlab

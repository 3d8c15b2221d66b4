// The browser's frame loop: the page calls one step per animation frame (requestAnimationFrame,
// through emscripten_set_main_loop_arg); main returns at once and the runtime stays alive.
#include <emscripten.h>

#include <exception>
#include <iostream>
#include <memory>

#include "app/frame_loop.hpp"
#include "app/share.hpp"
#include "core/params.hpp"

namespace shadowlab {
namespace {

const ParamRegistry* g_params = nullptr;

struct Loop {
  FrameStep step;
  int frame = 0;
};

void finish(Loop* loop, int code) {
  g_params = nullptr;  // the run's registry is gone
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
    exit = loop->step(loop->frame);
    if (!exit)
      EM_ASM(
          {
            if (Module.onFrame) Module.onFrame($0);
          },
          loop->frame);  // the page's figures
    ++loop->frame;
  } catch (const std::exception& e) {  // the lesson's own code reports and exits; this is a last resort
    std::cerr << "shadowlab: the frame loop stopped: " << e.what() << '\n';
    exit = 1;
  }
  if (exit) finish(loop, *exit);
}

}  // namespace

void exposeParams(const ParamRegistry* params) { g_params = params; }

int runFrames(FrameStep step) {
  emscripten_set_main_loop_arg(tick, new Loop{std::move(step)}, 0, false);
  return 0;
}

}  // namespace shadowlab

// Module.ccall('shadowlab_param', 'string', ['string'], [NAME]): the value as --set takes it, or ""
// for a name the lesson does not have (or before the lesson started).
extern "C" EMSCRIPTEN_KEEPALIVE const char* shadowlab_param(const char* name) {
  static std::string value;
  value.clear();
  if (shadowlab::g_params && shadowlab::g_params->has(name)) value = shadowlab::g_params->get(name);
  return value.c_str();
}

// Module.ccall('shadowlab_share', 'string', [], []): what the panel's "copy link" does (the page's
// address becomes the view's link), and its status line; "" before the lesson started.
extern "C" EMSCRIPTEN_KEEPALIVE const char* shadowlab_share() {
  static std::string status;
  status = shadowlab::g_params ? shadowlab::shareView(shadowlab::g_params->changed(), "") : "";
  return status.c_str();
}

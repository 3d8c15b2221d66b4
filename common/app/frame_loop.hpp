#pragma once
// Who calls the frames. Natively the lesson owns the loop; in a browser the page does (one call per
// animation frame, emscripten_set_main_loop), so the loop is a function of the platform, given
// one step: step(frame) draws that frame, or returns the run's exit code when the run is over.
#include <functional>
#include <optional>

namespace shadowlab {

class ParamRegistry;

using FrameStep = std::function<std::optional<int>(int frame)>;

// Natively: step(0), step(1), ... until one returns an exit code, which this returns. In a browser
// (frame_loop_web.cpp) it returns 0 at once and the page's animation frames call step; the exit
// code goes to the page (Module.onLessonExit(code)) when the run ends.
int runFrames(FrameStep step);

// The page may read the running lesson's parameters (shadowlab_param(NAME) from JavaScript: the
// browser tests check that a key press changed the parameter it names). Natively nothing.
void exposeParams(const ParamRegistry* params);

}  // namespace shadowlab

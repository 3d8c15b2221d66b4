#pragma once
// The Lesson base: a lesson is a class with a few hooks; the framework (app.cpp) owns the loop, the
// context, the UI header, the command line, presets, timers and the camera.
//
//   declare(params)  register every field of the lesson's Params (once; drives UI/CLI/presets)
//   init()           create GL resources (the context is current); throw to report a missing file
//   resize(w, h)     the framebuffer changed size
//   update(frame)    advance animation (dt in seconds)
//   render(frame)    draw into frame.framebuffer, timing each pass with scope("name")
//   gui()            the lesson's own ImGui widgets (the parameter panel is automatic)
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "app/debug_draw.hpp"
#include "app/exercises.hpp"
#include "app/frame_info.hpp"
#include "app/measurement.hpp"
#include "core/params.hpp"
#include "gl/timer.hpp"

namespace shadowlab {

struct LessonInfo {
  std::string number;       // "01"
  std::string name;         // "01_lighting": folder under lessons/ and shaders/
  std::string title;        // "Lighting"
  std::string summary;      // one line for the launcher
  int difficulty = 1;       // 1 (intro) to 5
  std::string help;         // F1 overlay: controls and what to try (several lines)
  bool measurable = false;  // computes V_i: gets the ground-truth overlay and --measure (measureSource())
  int minutes = 0;          // time in class (the lesson README's "Time and prerequisites")
  std::vector<std::string> prerequisites;  // lesson numbers a student should have done first ({"02"})
  // The counters the compact header shows (by name, those present this frame); every counter is in
  // the stats (F2). The ground truth's figures (misclassified, aliasing m, soft error) come with M.
  std::vector<std::string> keyFigures;
};

// A corner of the frame a lesson (or the framework's god view) draws a view into, in GL pixels
// (origin bottom-left): the UI keeps clear of it.
struct Inset {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;
};

// Counters of skipped or spent work that the header shows next to the timings
// ("culled casters 12 / 40", "shadow triangles 120k").
struct Counter {
  std::string name;
  std::string value;
};

class Lesson {
 public:
  virtual ~Lesson() = default;
  virtual LessonInfo info() const = 0;
  virtual void declare(ParamRegistry& params) = 0;
  virtual void init() = 0;
  virtual void resize(int width, int height) {}
  virtual void update(const FrameInfo& frame) {}
  virtual void render(const FrameInfo& frame) = 0;
  virtual void gui() {}
  // For measurable lessons: the scene and lights the ground truth traces (common/app/measurement.hpp).
  virtual MeasureSource measureSource() { return {}; }
  // Replaying a recorded camera and light path (--replay): move the lesson's primary light.
  virtual void applyPathLight(const glm::vec3& position, const glm::vec3& direction) {}
  // After render(): the lit scene once more from frame's camera (view, projection, eye) into
  // frame.framebuffer, this frame's shadows as they are (no map redrawn, nothing refitted). The
  // shimmer figures evaluate a frame's shadows at the previous frame's very points this way when
  // the camera moved. False: the lesson cannot (the figures then follow points by reprojection).
  virtual bool redrawLit(const FrameInfo& frame) { return false; }
  // redrawLit with the timers off: the frame's own passes are its cost; this draw only measures it.
  bool redrawLitUntimed(const FrameInfo& frame) {
    const bool timed = timers.enabled();
    timers.setEnabled(false);
    const bool drawn = redrawLit(frame);
    timers.setEnabled(timed);
    return drawn;
  }

  // Set up by the framework before init(); lessons use them freely.
  OrbitCamera camera;
  gl::GpuTimers timers;
  std::vector<Counter> counters;  // refilled by the lesson each frame
  DebugDraw debug;                // shapes for the god view; cleared by the framework every frame
  std::vector<Inset> insets;      // views drawn into corners this frame; cleared by the framework
  std::vector<Legend> legends;    // colour keys of the heatmaps drawn this frame; cleared by the framework
  Exercises exercises;            // add() them in declare(): the exercises panel and the stub banner
  bool panelsHidden = false;      // H pressed once: gui() draws only what explains the picture (labels), no window

  gl::TimerScope scope(const std::string& pass) { return gl::TimerScope(timers, pass); }
};

// Runs a lesson with the shared command line. Returns the process exit code:
// 0 ok, 1 runtime failure (missing file, shader error headless), 2 bad command line or parameter,
// 3 GL errors seen with --strict-gl. The framework owns the lesson so that its GL objects are
// released while the context still exists:  int main(int c, char** v) { return runLesson<MyLesson>(c, v); }
int runLesson(const std::function<std::unique_ptr<Lesson>()>& make, int argc, char** argv);
template <class L>
int runLesson(int argc, char** argv) {
  return runLesson([] { return std::unique_ptr<Lesson>(new L()); }, argc, argv);
}

// Whose code runs where a lesson has exercises: the reference in common/algorithms, or the
// student's exercises.cpp (the parameter `impl`; `why` says what it switches in this lesson).
enum class Impl { Reference, Student };
void declareImpl(ParamRegistry& params, Impl* impl, const std::string& why);

// The camera's pose as hidden parameters (camera.yaw, ...), so presets snapshot it.
void declareCamera(ParamRegistry& params, OrbitCamera& camera);
// Light `index` as parameters lightN.enabled (hotkey N+1), .kind, .position, .direction, .color,
// .intensity, .attenuation, .spot_inner, .spot_outer: every lesson's lights look the same.
void declareLight(ParamRegistry& params, int index, Light& light);
// Every light of a lesson: lights[i] as light<i>.
void declareLights(ParamRegistry& params, std::span<Light> lights);

}  // namespace shadowlab

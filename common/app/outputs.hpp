#pragma once
// What a lesson run writes besides its window: screenshots (--screenshot, F12), the per-pass
// timing CSV (--bench) and the ground-truth figures (--measure), for tests, benchmarks and slides.
#include <fstream>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "app/measurement.hpp"
#include "gl/timer.hpp"

namespace shadowlab {

// out/screenshots/NN_name_YYYYmmdd_HHMMSS.png
std::string screenshotName(const LessonInfo& info);
// Reads `fbo` back and writes a PNG, creating the folder. Throws std::runtime_error naming the path.
void saveScreenshot(const std::string& path, unsigned fbo, int width, int height);
// The share of (nearly) black pixels in `fbo`: below 24 of 255 in every channel, so the lessons'
// clear colour (0.05, 0.06, 0.08) counts too, and an empty frame is "black" (the stub banner).
double blackShare(unsigned fbo, int width, int height);

// --bench FILE: one row per pass per frame (GPU ms arrive a few frames late; each row carries the
// frame that issued it), plus the CPU time of each whole frame, its draw calls and render scale.
class BenchLog {
 public:
  // False when the file cannot be written.
  bool open(const std::string& path);
  bool isOpen() const { return out_.is_open(); }
  // A frame's time, its draw calls and the frame budget's render scale (1: the requested size).
  void frame(int index, double frameMs, int drawCalls, float renderScale, gl::GpuTimers& timers);
  void flush(gl::GpuTimers& timers);
  // Writes what is left; throws std::runtime_error naming the file when any write failed.
  void close();

 private:
  struct FrameRow {
    double ms = 0;
    int drawCalls = 0;
    float scale = 1;
  };
  std::ofstream out_;
  std::string path_;
  std::vector<FrameRow> frames_;
};

// B's half of an A/B split: its preset and its own whole-frame measurement.
struct SplitFigures {
  std::string preset;
  const MeasureResult& result;
};

// --measure FILE: the last frame's figures against ground truth as JSON, and its heatmaps as PNGs
// beside it (FILE minus .json, plus _error.png / _aliasing.png); with the A/B split on, B's figures
// too (under "b"). Throws std::runtime_error.
void writeMeasurementJson(const std::string& path, const LessonInfo& info, const MeasureResult& result,
                          const std::vector<Counter>& counters, const gl::GpuTimers& timers,
                          const SplitFigures* b = nullptr);

}  // namespace shadowlab

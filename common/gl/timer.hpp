#pragma once
// Per-pass timing without stalls: each named pass gets a ring of timestamp query pairs; a result is
// read only when the GPU says it is available (a few frames later), so the CPU never waits.
// CPU time of the same scope is measured alongside. Both are averaged over a sliding window.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "gl/objects.hpp"

namespace shadowlab::gl {

// One resolved measurement, for benchmarks: which pass, in which frame it was issued.
struct TimingSample {
  std::string pass;
  int frame = 0;
  double gpuMs = 0, cpuMs = 0;
};

struct PassTiming {
  std::string name;
  double gpuMs = 0, cpuMs = 0;          // averaged over the window
  double lastGpuMs = 0, lastCpuMs = 0;  // the latest resolved sample
  int samples = 0;
  bool drawn = false;  // begun in the current frame; false for a pass skipped there (a map reused)
};

class GpuTimers {
 public:
  static constexpr int kRing = 6;     // frames in flight before a query pair is reused
  static constexpr int kWindow = 30;  // frames in the average

  // Synchronous: glFinish at both ends of every pass, so a pass's CPU ms is what it really cost.
  // A software rasteriser (llvmpipe) does its work deferred, at a later flush: its timestamp
  // queries then report next to nothing for the pass that caused it. The app turns this on for
  // software renderers (SHADOWLAB_SYNC_TIMERS=0/1 overrides); it costs the overlap between passes.
  void setSynchronous(bool on) { sync_ = on; }
  bool synchronous() const { return sync_; }
  // Off: begin/end do nothing (the god view re-renders the lesson; its passes must not be counted).
  // Turned off while a pass is open, the passes begun inside do nothing and the open one still
  // ends: one figure for a whole stretch (lesson 10's four-up quarters).
  void setEnabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }
  void begin(const std::string& pass);
  void end();
  // Once a frame, after the passes: collects every result that is ready.
  void collect();
  // The frame number stamped on passes begun from now on (the app sets it each frame); a new frame
  // clears every pass's `drawn`.
  void setFrame(int frame);
  // Keep every resolved sample for takeSamples() (benchmarks); off by default.
  void keepSamples(bool on) { keep_ = on; }
  std::vector<TimingSample> takeSamples() { return std::exchange(samples_, {}); }
  const std::vector<PassTiming>& passes() const { return timings_; }
  const PassTiming* find(const std::string& pass) const;
  double totalGpuMs() const;

 private:
  struct Slot {
    Query start, stop;
    bool pending = false;
    double cpuMs = 0;
    int frame = 0;
  };
  struct Pass {
    std::string name;
    std::array<Slot, kRing> ring;
    int next = 0;
    std::vector<double> gpuHistory, cpuHistory;
  };
  Pass& pass(const std::string& name);
  std::vector<Pass> passes_;
  std::vector<PassTiming> timings_;
  std::vector<TimingSample> samples_;
  bool keep_ = false;
  bool enabled_ = true;
  bool sync_ = false;
  int frame_ = 0;
  int open_ = -1;
  double openCpuStart_ = 0;
};

// Times a scope: `auto t = timers.scope("shadow map");`
class TimerScope {
 public:
  TimerScope(GpuTimers& t, const std::string& pass) : timers_(t) { timers_.begin(pass); }
  ~TimerScope() { timers_.end(); }
  TimerScope(const TimerScope&) = delete;
  TimerScope& operator=(const TimerScope&) = delete;

 private:
  GpuTimers& timers_;
};

}  // namespace shadowlab::gl

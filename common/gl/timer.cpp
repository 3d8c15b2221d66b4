#include "gl/timer.hpp"

#include "gl/caps.hpp"

#include <chrono>
#include <numeric>
#include <stdexcept>

#include "gl/debug.hpp"

namespace shadowlab::gl {
namespace {
double cpuNowMs() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}
double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}
void pushWindow(std::vector<double>& v, double x, std::size_t window) {
  v.push_back(x);
  if (v.size() > window) v.erase(v.begin());
}
}  // namespace

GpuTimers::Pass& GpuTimers::pass(const std::string& name) {
  for (auto& p : passes_)
    if (p.name == name) return p;
  passes_.push_back(Pass{name, {}, 0, {}, {}});
  for (auto& slot : passes_.back().ring) {
    slot.start = makeQuery(name + ".start");
    slot.stop = makeQuery(name + ".stop");
  }
  timings_.push_back(PassTiming{name});
  return passes_.back();
}

void GpuTimers::setFrame(int frame) {
  if (frame != frame_)
    for (PassTiming& t : timings_) t.drawn = false;
  frame_ = frame;
}

void GpuTimers::begin(const std::string& name) {
  checkPassErrors("the start of", name);  // strict mode without KHR_debug: errors named by their pass
  if (!enabled_) return;
  if (open_ >= 0) throw std::logic_error("GpuTimers: pass '" + name + "' begun inside '" + passes_[open_].name + "'");
  Pass& p = pass(name);
  open_ = int(&p - passes_.data());
  timings_[std::size_t(open_)].drawn = true;
  Slot& slot = p.ring[p.next];
  if (slot.pending) {
    // The ring wrapped before the GPU answered: drop that sample rather than stall.
    slot.pending = false;
  }
  if (sync_) glFinish();  // earlier work must not be billed to this pass
  if (caps().timerQuery) glQueryCounter(slot.start.id(), GL_TIMESTAMP);
  openCpuStart_ = cpuNowMs();
}

void GpuTimers::end() {
  if (!enabled_) return;
  if (open_ < 0) throw std::logic_error("GpuTimers: end() without begin()");
  Pass& p = passes_[open_];
  checkPassErrors("the end of", p.name);
  Slot& slot = p.ring[p.next];
  if (caps().timerQuery) glQueryCounter(slot.stop.id(), GL_TIMESTAMP);
  if (sync_) glFinish();
  slot.cpuMs = cpuNowMs() - openCpuStart_;
  slot.frame = frame_;
  slot.pending = true;
  p.next = (p.next + 1) % kRing;
  open_ = -1;
}

void GpuTimers::collect() {
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    Pass& p = passes_[i];
    PassTiming& t = timings_[i];
    for (int k = 0; k < kRing; ++k) {  // oldest first: the slot begin() reuses next
      Slot& slot = p.ring[(p.next + k) % kRing];
      if (!slot.pending) continue;
      GLuint64 start = 0, stop = 0;
      if (caps().timerQuery) {  // else (WebGL2) the pass's CPU time stands for both
        GLint ready = 0;
        glGetQueryObjectiv(slot.stop.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (!ready) break;  // later ones are not ready either
        glGetQueryObjectui64v(slot.start.id(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(slot.stop.id(), GL_QUERY_RESULT, &stop);
      }
      slot.pending = false;
      t.lastGpuMs = caps().timerQuery ? double(stop - start) * 1e-6 : slot.cpuMs;
      t.lastCpuMs = slot.cpuMs;
      if (keep_) samples_.push_back({p.name, slot.frame, t.lastGpuMs, t.lastCpuMs});
      pushWindow(p.gpuHistory, t.lastGpuMs, kWindow);
      pushWindow(p.cpuHistory, t.lastCpuMs, kWindow);
      ++t.samples;
    }
    t.gpuMs = mean(p.gpuHistory);
    t.cpuMs = mean(p.cpuHistory);
  }
}

const PassTiming* GpuTimers::find(const std::string& name) const {
  for (const auto& t : timings_)
    if (t.name == name) return &t;
  return nullptr;
}

double GpuTimers::totalGpuMs() const {
  double sum = 0;
  for (const auto& t : timings_) sum += t.gpuMs;
  return sum;
}

}  // namespace shadowlab::gl

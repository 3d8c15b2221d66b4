#include "app/outputs.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/image.hpp"
#include "gl/texture.hpp"

namespace shadowlab {
namespace {

void createParent(const std::string& path) {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
}

// Buffered streams report a full disk only when flushed: close and look, naming the file.
void closeChecked(std::ofstream& out, const std::string& flag, const std::string& path) {
  out.close();
  if (!out) throw std::runtime_error(flag + ": cannot write " + path + ": " + std::strerror(errno));
}

}  // namespace

std::string screenshotName(const LessonInfo& info) {
  std::time_t t = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&t));
  return "out/screenshots/" + info.name + "_" + stamp + ".png";
}

void saveScreenshot(const std::string& path, unsigned fbo, int w, int h) {
  createParent(path);
  savePng(path, gl::readPixels(fbo, w, h));
}

bool BenchLog::open(const std::string& path) {
  path_ = path;
  out_.open(path);
  if (!out_) return false;
  out_ << "frame,pass,gpu_ms,cpu_ms,frame_ms,draw_calls,render_scale\n";
  return true;
}

void BenchLog::close() { closeChecked(out_, "--bench", path_); }

void BenchLog::frame(int index, double frameMs, int drawCalls, float renderScale, gl::GpuTimers& timers) {
  frames_.resize(std::size_t(index) + 1);
  frames_[std::size_t(index)] = {frameMs, drawCalls, renderScale};
  flush(timers);
}

void BenchLog::flush(gl::GpuTimers& timers) {
  for (const auto& s : timers.takeSamples()) {
    const FrameRow f = s.frame < int(frames_.size()) ? frames_[std::size_t(s.frame)] : FrameRow{};
    out_ << s.frame << ',' << s.pass << ',' << s.gpuMs << ',' << s.cpuMs << ',' << f.ms << ',' << f.drawCalls << ','
         << f.scale << '\n';
  }
}

// The figures of one measured frame: hard errors (or soft RMSE) and, where a map was sampled,
// the aliasing factor.
nlohmann::ordered_json figures(const MeasureResult& r) {
  nlohmann::ordered_json j;
  j["width"] = r.width;
  j["height"] = r.height;
  if (r.hasTemporal) {
    const auto& t = r.temporal;
    j["temporal"] = {{"pixels", t.pixels},
                     {"flips", t.flips},
                     {"reference_flips", t.referenceFlips},
                     {"extra_flips", t.extraFlips},
                     {"extra_flip_pct", t.extraFlipPct},
                     {"reference_flip_pct", t.referenceFlipPct},
                     {"mean_change", t.meanChange},
                     {"reference_mean_change", t.referenceMeanChange},
                     {"extra_change", t.extraChange},
                     {"redrawn", r.redrawn},
                     {"reprojected", r.reprojected},
                     {"unmatched", r.unmatched}};
  }
  if (r.soft) {
    const auto& s = r.soft_;
    j["soft"] = {{"pixels", s.pixels},
                 {"rmse", s.rmse},
                 {"max_abs", s.maxAbs},
                 {"umbra_pixels", s.umbraPixels},
                 {"umbra_over_pct", s.umbraOverPct},
                 {"umbra_under_pct", s.umbraUnderPct},
                 {"bleed_pct", s.bleedPct}};
    if (s.noiseFloor >= 0) j["soft"]["reference_noise_rmse"] = s.noiseFloor;
  } else {
    const auto& h = r.hard;
    j["hard"] = {{"facing_pixels", h.facingPixels},         {"reference_shadowed", h.referenceShadowed},
                 {"misclassified", h.misclassified},        {"leaks", h.leaks},
                 {"false_shadows", h.falseShadows},         {"edge_pixels", h.edgePixels},
                 {"misclassified_pct", h.misclassifiedPct}, {"leak_pct", h.leakPct},
                 {"false_shadow_pct", h.falseShadowPct},    {"edge_tolerant_pct", h.edgeTolerantPct}};
  }
  j["nonfinite"] = {{"visibility", r.nonFiniteVisibility}, {"texel_jacobian", r.nonFiniteJacobian}};
  auto aliasing = [](const measure::AliasingStats& a) {
    return nlohmann::ordered_json{{"pixels", a.pixels}, {"mean", a.mean}, {"rms", a.rms},
                                  {"p95", a.p95},       {"max", a.max},   {"share_above_1", a.shareAbove1}};
  };
  if (r.hasAliasing) j["aliasing"] = aliasing(r.aliasing);
  if (r.hasBand) {  // near shadow edges (MeasureSource::edgeBand)
    const auto& b = r.band;
    j["edge_band"] = {{"radius", r.bandRadius},           {"pixels", b.facingPixels},
                      {"misclassified", b.misclassified}, {"leaks", b.leaks},
                      {"false_shadows", b.falseShadows},  {"misclassified_pct", b.misclassifiedPct}};
    if (r.hasAliasing) j["edge_band"]["aliasing"] = aliasing(r.bandAliasing);
  }
  return j;
}

void writeMeasurementJson(const std::string& path, const LessonInfo& info, const MeasureResult& r,
                          const std::vector<Counter>& counters, const gl::GpuTimers& timers, const SplitFigures* b) {
  if (!r.valid)
    throw std::runtime_error("--measure: " +
                             (r.unmeasurable.empty()
                                  ? std::string("nothing was measured (does the lesson describe its scene?)")
                                  : r.unmeasurable));
  nlohmann::ordered_json j;
  j["lesson"] = info.name;
  j.update(figures(r));
  // The A/B split: B (a preset over the same camera) measured on its own whole frame.
  if (b && b->result.valid) {
    j["b"] = figures(b->result);
    j["b"]["preset"] = b->preset;
  }
  j["ground_truth_ms"] = r.groundTruthMs;
  j["gpu_ms"] = nlohmann::ordered_json::object();
  j["cpu_ms"] = nlohmann::ordered_json::object();
  for (const auto& t : timers.passes()) {
    j["gpu_ms"][t.name] = t.gpuMs;
    j["cpu_ms"][t.name] = t.cpuMs;
  }
  j["counters"] = nlohmann::ordered_json::object();
  for (const auto& c : counters) j["counters"][c.name] = c.value;

  createParent(path);
  std::ofstream out(path);
  out << j.dump(2) << '\n';
  closeChecked(out, "--measure", path);  // before the heatmaps: nothing lands beside a file that failed
  const std::string stem =
      path.size() > 5 && path.substr(path.size() - 5) == ".json" ? path.substr(0, path.size() - 5) : path;
  savePng(stem + "_error.png", r.errorHeatmap);
  if (r.hasAliasing) savePng(stem + "_aliasing.png", r.aliasingHeatmap);
  savePng(stem + "_reference.png", r.referenceImage);  // the ground truth's visibility, as the overlay shows it
}

double blackShare(unsigned fbo, int width, int height) {
  std::vector<unsigned char> rgba(std::size_t(width) * std::size_t(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  std::size_t black = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) black += std::max({rgba[i], rgba[i + 1], rgba[i + 2]}) < 24;
  return rgba.empty() ? 0.0 : double(black) / double(rgba.size() / 4);
}

}  // namespace shadowlab

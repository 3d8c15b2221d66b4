#pragma once
// A/B split screen: the same frame rendered with two parameter sets, A (the current settings) left
// of a draggable divider and B (a preset, over the current camera) right of it, each half labelled
// with its settings and, for measurable lessons, its error against ground truth.
#include <functional>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "app/measurement.hpp"
#include "core/params.hpp"
#include "gl/objects.hpp"

namespace shadowlab {

class AbSplit {
 public:
  // After the presets are loaded: B is chosen among them.
  void declare(ParamRegistry& params, const PresetFile& presets);
  bool enabled() const { return enabled_ && !presetNames_.empty(); }
  float divider() const { return divider_; }
  void setDivider(float x) { divider_ = x < 0.02f ? 0.02f : x > 0.98f ? 0.98f : x; }

  // Renders B into its own target (B's passes are not timed) and copies the part right of the
  // divider over `frame`. `measured` is A's measurement (B is measured with the same settings).
  void draw(const FrameInfo& frame, ParamRegistry& params, const PresetFile& presets, Lesson& lesson,
            const Measurement* measured, const std::function<void(const FrameInfo&)>& render);
  // Labels for the UI, naming each half by what it is: "A: technique=uniform" (the settings that
  // differ from B's) and "B: versus_volumes_b (technique=volumes, ...)", each with its key figures
  // (A's: `key`; B's: its counters named in `keyFigures`, LessonInfo::keyFigures) and, measured
  // (M), its error against the ground truth.
  std::string labelA(const Measurement* measured, const std::vector<Counter>& key) const;
  std::string labelB(const std::vector<std::string>& keyFigures) const;
  // Measure B at full resolution in the next frame too (headless --measure).
  void requestFullResolution() { measurementB_.requestFullResolution(); }
  // B's preset and its measurement of the last frame (valid when the lesson is measurable).
  const std::string& presetB() const { return presetNames_[std::size_t(preset_)]; }
  const Measurement& measurementB() const { return measurementB_; }

 private:
  bool enabled_ = false;
  int preset_ = 0;
  float divider_ = 0.5f;
  std::vector<std::string> presetNames_;
  gl::Framebuffer fbo_;
  gl::RenderTarget target_;
  Measurement measurementB_;
  std::string figuresB_;
  std::string whatA_, whatB_;       // the settings that set each half apart
  std::vector<Counter> countersB_;  // B's figures in the last frame
};

}  // namespace shadowlab

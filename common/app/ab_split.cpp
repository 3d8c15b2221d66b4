#include "app/ab_split.hpp"

#include <cstdio>
#include <map>

#include "gl/gl.hpp"

namespace shadowlab {
namespace {

// Framework settings B shares with A: the same view of the same scene, measured the same way.
bool sharedWithB(const std::string& name) {
  for (const char* prefix : {"camera.", "ab.", "view.", "measure."})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

std::string figures(const Measurement* m) {
  if (!m || !m->result().valid) return "";
  const MeasureResult& r = m->result();
  char buf[96];
  if (r.soft) std::snprintf(buf, sizeof buf, "RMSE %.4f", r.soft_.rmse);
  else std::snprintf(buf, sizeof buf, "misclassified %.2f%% (leaks %.2f%%)", r.hard.misclassifiedPct, r.hard.leakPct);
  return buf;
}

// What sets one half apart: "technique=volumes, scene=showcase +2 more" (the values of `mine` that
// differ from `other`'s, the settings both halves share left out).
std::string differences(const std::map<std::string, std::string>& mine,
                        const std::map<std::string, std::string>& other) {
  std::string s;
  int listed = 0, more = 0;
  for (const auto& [name, value] : mine) {
    const auto it = other.find(name);
    if (sharedWithB(name) || (it != other.end() && it->second == value)) continue;
    if (listed == 3) {
      ++more;
      continue;
    }
    const std::string shown = value.size() > 24 ? value.substr(0, 21) + "..." : value;
    s += (listed++ ? ", " : "") + name + "=" + shown;
  }
  return more ? s + " +" + std::to_string(more) + " more" : s;
}

// The lesson's first key figure among `counters`, on a line of its own.
std::string keyLines(const std::vector<Counter>& counters, const std::vector<std::string>& names) {
  std::string s;
  int n = 0;
  for (const std::string& name : names)
    for (const Counter& c : counters)
      if (c.name == name && n++ < 1) s += "\n" + c.name + ": " + c.value;
  return s;
}

}  // namespace

void AbSplit::declare(ParamRegistry& r, const PresetFile& presets) {
  presetNames_ = presets.names();
  if (presetNames_.empty()) return;  // nothing to compare with
  r.add("ab.enabled", &enabled_, "split screen: current settings (A, left) against a preset (B, right)").hotkey = "X";
  r.addChoice("ab.preset", &preset_, presetNames_, "the preset shown right of the divider");
  r.add("ab.divider", &divider_, 0.02f, 0.98f, "where the screen splits (drag it with the mouse)");
}

void AbSplit::draw(const FrameInfo& frame, ParamRegistry& params, const PresetFile& presets, Lesson& lesson,
                   const Measurement* measured, const std::function<void(const FrameInfo&)>& render) {
  if (target_.width != frame.width || target_.height != frame.height)
    target_ = gl::makeRenderTarget(frame.width, frame.height, "A/B: B");

  // Switch to B: the preset over the defaults, keeping A's view and the framework's settings.
  const auto a = params.snapshot();
  presets.apply(presetNames_[std::size_t(preset_)], params);
  ParamValues shared;
  for (const auto& [name, value] : a)
    if (sharedWithB(name)) shared.emplace_back(name, value);
  params.setAll(shared);

  FrameInfo b = frame;
  const std::vector<Counter> countersA = lesson.counters;  // the header shows A's work, not B's
  lesson.timers.setEnabled(false);
  lesson.update(b);
  // What sets the halves apart, each as its update left it: a lesson that derives parameters there
  // (lesson 10's equal texels sets every map's size) must not show them as a difference of B's.
  const auto bValues = params.snapshot();
  whatA_ = differences(a, bValues);
  whatB_ = differences(bValues, a);
  if (measured) measurementB_.mirror(*measured);
  b.framebuffer = measurementB_.begin(target_.fbo.id(), b);
  b.measureLight = measurementB_.measuredLight();
  glBindFramebuffer(GL_FRAMEBUFFER, b.framebuffer);
  glViewport(0, 0, frame.width, frame.height);
  render(b);
  if (measured) measurementB_.end(lesson.measureSource(), target_.fbo.id(), true);
  lesson.timers.setEnabled(true);
  countersB_ = lesson.counters;
  lesson.counters = countersA;
  figuresB_ = figures(measured ? &measurementB_ : nullptr);

  // Back to A exactly as it was.
  params.restore(a);

  const int x0 = int(divider_ * float(frame.width));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.fbo.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.framebuffer);
  glBlitFramebuffer(x0, 0, frame.width, frame.height, x0, 0, frame.width, frame.height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  // The divider itself.
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0 - 1, 0, 2, frame.height);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
}

std::string AbSplit::labelA(const Measurement* measured, const std::vector<Counter>& key) const {
  const std::string f = figures(measured);
  std::string lines;
  if (!key.empty()) lines = "\n" + key[0].name + ": " + key[0].value;
  return "A: " + (whatA_.empty() ? "the same settings as B" : whatA_) + lines + (f.empty() ? "" : "\n" + f);
}

std::string AbSplit::labelB(const std::vector<std::string>& keyFigures) const {
  return "B: " + presetNames_[std::size_t(preset_)] + (whatB_.empty() ? "" : " (" + whatB_ + ")") +
         keyLines(countersB_, keyFigures) + (figuresB_.empty() ? "" : "\n" + figuresB_);
}

}  // namespace shadowlab

#pragma once
// The framework's ImGui layer, the picture first: a compact header every lesson shares (title, ms
// and fps, the lesson's key figures, the ground truth's, shader errors), the F2 stats under it
// (renderer, per-pass ms, every counter), the F1 help overlay, the automatic parameter panel with
// presets (a title bar until F3 or a click opens it), and the UI scale for projectors.
#include <string>
#include <vector>

#include "app/context.hpp"
#include "app/exercises.hpp"
#include "app/lesson.hpp"
#include "core/params.hpp"

namespace shadowlab {

class Ui {
 public:
  void init(Context& context, float scale);
  void shutdown();
  void newFrame(double dt, int width, int height);  // size: headless only (GLFW knows its own)
  // Draws into the currently bound framebuffer; draw=false ends the frame without drawing (a
  // layout pass: auto-fit windows take their size from the frame before).
  void render(bool draw = true);
  bool wantsMouse() const;
  bool wantsKeyboard() const;

  void setScale(float scale);
  float scale() const { return scale_; }

  struct HeaderData {
    const LessonInfo* info = nullptr;
    std::string gpu;     // renderer and GL version
    double frameMs = 0;  // CPU frame time, averaged
    const std::vector<gl::PassTiming>* passes = nullptr;
    const std::vector<Counter>* counters = nullptr;  // every figure: the stats
    std::vector<Counter> key;                        // the header's few (LessonInfo::keyFigures, the ground truth's)
    std::vector<std::string> errors;                 // shader and file errors, file:line first
    std::string status;                              // transient message ("saved screenshot to ...")
    bool softwareRenderer = false;                   // time passes on the CPU: its timestamps miss deferred work
    std::string renderScale;  // the frame budget's "render scale 0.60 (software renderer)", or ""
  };
  void header(const HeaderData& data);
  // F2: the renderer, the frame budget, the pass table and every counter, under the header.
  void stats(const HeaderData& data, bool* open);
  void help(const LessonInfo& info, const ParamRegistry& params, bool* open);
  // A/B split: a label at the bottom of each half (before legends(): the stack there stays above).
  void splitLabels(float divider, const std::string& a, const std::string& b);
  // Corners the frame shows views in (after newFrame, before paramPanel): the panel stays above
  // those in its column; they are in layout() too.
  void reserve(const std::vector<Inset>& insets, int framebufferHeight);
  // The colour keys of this frame's heatmaps, bottom left, one under the other (before header():
  // the header then stops above them).
  void legends(const std::vector<Legend>& legends);
  // Returns true when a parameter changed. Collapsed to its title bar unless *open (F3, or a click
  // on the title bar, which writes *open back).
  // `lesson` ("03_shadow_quality") names the view "copy link" gives.
  bool paramPanel(ParamRegistry& params, PresetFile& presets, const std::string& lesson, std::string& status,
                  bool* open);
  // The lesson's exercises with their states (bottom left); true when "run the cases again" was pressed.
  bool exercisesPanel(const Exercises& exercises);
  // A banner across the top of the frame: the stub banner while impl=student.
  void banner(const std::string& text);
  // --panel: the panel with these parameters only, no preset row, and no header, stats, help or
  // exercises window (a lesson inside a slide). Throws ParamError on a name the lesson lacks.
  void panelOnly(const std::vector<std::string>& names, const ParamRegistry& params);

  // Where this frame's UI sits, in framebuffer pixels (windows by title; the A/B labels as
  // "A label" / "B label"): --ui-layout writes it, tests check nothing overlaps.
  struct Rect {
    std::string name;
    float x = 0, y = 0, w = 0, h = 0;
  };
  const std::vector<Rect>& layout() const { return layout_; }

 private:
  void recordWindow(const char* name);
  // The panel's two parts: the preset row (pick, name, save, defaults) and the parameters by
  // group. Each returns the right edge of its widgets; `changed` is set when a value changed.
  float presetRows(ParamRegistry& params, PresetFile& presets, const std::string& lesson, std::string& status,
                   float room, bool& changed);
  float parameterRows(ParamRegistry& params, std::string& status, float room, float common, bool& changed);
  bool initialised_ = false;
  bool headless_ = false;
  float scale_ = 1.0f;
  char presetName_[64] = "my_preset";
  int presetIndex_ = -1;
  std::vector<Rect> layout_;
  // The height a window from the top (8 px down) may take in the column [left, right) above this
  // frame's insets, at most `height`.
  float roomAbove(float left, float right, float height) const;
  std::vector<Rect> reserved_;  // this frame's insets, top-left origin
  float legendTop_ = 1e9f;      // the top of the bottom-left stack (legend, exercises) this frame
  float headerBottom_ = 0;      // where the stats window starts
  Rect legendRect_;             // this frame's legend (bottom right): the panel stops above it
  bool panelApplied_ = false;   // the open state last given to ImGui (a click may change it there)
  bool panelSet_ = false;
  bool exercisesOpen_ = false;     // last frame's: collapsed, the exercises' bar is as narrow as its title
  std::vector<std::string> only_;  // --panel's parameters; empty: every window as usual
};

// --ui-layout FILE: the viewport and the UI's rectangles as JSON. Throws std::runtime_error.
void writeUiLayout(const std::string& path, int width, int height, const std::vector<Ui::Rect>& rects);

}  // namespace shadowlab

#include "app/ui.hpp"
#include "app/ui_layout.hpp"

#include "gl/caps.hpp"
#include "core/hotkeys.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // the context's windows: the lesson's own ones in the layout
#include <nlohmann/json.hpp>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace shadowlab {

namespace {
ImGuiStyle g_baseStyle;
}

void Ui::init(Context& context, float scale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini littering the working directory
  ImGui::StyleColorsDark();
  g_baseStyle = ImGui::GetStyle();
  headless_ = context.headless();
  if (!headless_) ImGui_ImplGlfw_InitForOpenGL(context.window(), true);
  ImGui_ImplOpenGL3_Init(gl::caps().gles ? "#version 300 es" : "#version 410 core");
  initialised_ = true;
  setScale(scale);
}

void Ui::shutdown() {
  if (!initialised_) return;
  ImGui_ImplOpenGL3_Shutdown();
  if (!headless_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  initialised_ = false;
}

void Ui::setScale(float scale) {
  scale_ = std::clamp(scale, 0.5f, 4.0f);
  ImGuiStyle& style = ImGui::GetStyle();
  style = g_baseStyle;
  style.ScaleAllSizes(scale_);
  ImGui::GetIO().FontGlobalScale = scale_;
}

void Ui::newFrame(double dt, int width, int height) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  if (!headless_) ImGui_ImplGlfw_NewFrame();
  else io.DisplaySize = ImVec2(float(width), float(height));
  io.DeltaTime = float(std::max(dt, 1e-4));
  ImGui::NewFrame();
  layout_.clear();
  reserved_.clear();
  legendTop_ = 1e9f;
  legendRect_ = {};
}

void Ui::recordWindow(const char* name) {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  layout_.push_back({name, pos.x, pos.y, size.x, size.y});
}

void Ui::reserve(const std::vector<Inset>& insets, int framebufferHeight) {
  for (const Inset& i : insets) {
    const Rect r{i.name, float(i.x), float(framebufferHeight - i.y - i.height), float(i.width), float(i.height)};
    reserved_.push_back(r);
    layout_.push_back(r);
  }
}

float Ui::roomAbove(float left, float right, float height) const {
  for (const Rect& r : reserved_)  // an inset under the column [left, right): stop above it
    if (r.x < right && r.x + r.w > left) height = std::min(height, r.y - 16 * scale_);
  return height;
}

void Ui::legends(const std::vector<Legend>& legends) {
  if (legends.empty()) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // Bottom right: the bottom-left corner holds the exercises and the post-projective view's inset
  // (the legend covered that inset); above the A/B labels when the split is on (splitLabels() ran
  // first and lowered legendTop_) and above the insets in the right column (the god view's).
  const float right = vp->Size.x - 8 * scale_;
  const ImGuiStyle& style = ImGui::GetStyle();
  float width = 0, lines = 0;  // at the UI's font size
  for (const Legend& l : legends) {
    width = std::max(width, ImGui::CalcTextSize(l.title.c_str()).x);
    for (const Legend::Entry& e : l.entries)
      width =
          std::max(width, ImGui::GetFontSize() * 1.6f + style.ItemSpacing.x + ImGui::CalcTextSize(e.label.c_str()).x);
    lines += 1.0f + float(l.entries.size());
  }
  float bottom = std::min(vp->Size.y, legendTop_) - 8 * scale_;
  // The right column (the header keeps the left), under the panel's title bar; smaller type where a
  // projector's UI scale and several views leave it little room (down to 45 %: at UI scale 2, about
  // the size of scale 1).
  const float top = 16 * scale_ + ImGui::GetFrameHeight();
  const float columnWidth = vp->Size.x * (1.0f - kHeaderShare) - 16 * scale_;
  const float spacing = style.ItemSpacing.y * 0.5f;  // the entries a little closer than elsewhere
  auto fit = [&](float b) {
    return std::clamp(std::min((columnWidth - 2 * style.WindowPadding.x) / std::max(width, 1.0f),
                               (b - top - 2 * style.WindowPadding.y - lines * spacing) /
                                   std::max(lines * ImGui::GetFontSize(), 1.0f)),
                      0.45f, 1.0f);
  };
  float fontScale = fit(bottom);
  const float left = right - width * fontScale - 2 * style.WindowPadding.x;
  for (const Rect& r : reserved_)  // above every inset under its own columns
    if (r.x < right && r.x + r.w > left && r.y < bottom) bottom = std::min(bottom, r.y - 8 * scale_);
  fontScale = std::min(fontScale, fit(bottom));
  ImGui::SetNextWindowPos(ImVec2(right, bottom), ImGuiCond_Always, ImVec2(1, 1));
  ImGui::SetNextWindowBgAlpha(1.0f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoInputs;
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(style.ItemSpacing.x, spacing));
  ImGui::Begin("Legend", nullptr, flags);
  ImGui::SetWindowFontScale(fontScale);
  for (const Legend& l : legends) {
    ImGui::TextUnformatted(l.title.c_str());
    for (const Legend::Entry& e : l.entries) {
      const ImVec2 box(ImGui::GetFontSize() * 1.6f, ImGui::GetFontSize());
      ImGui::ColorButton(e.label.c_str(), ImVec4(e.color.x, e.color.y, e.color.z, 1.0f),
                         ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoBorder, box);
      ImGui::SameLine();
      ImGui::TextUnformatted(e.label.c_str());
    }
  }
  recordWindow("Legend");
  legendRect_ = layout_.back();
  ImGui::End();
  ImGui::PopStyleVar();
}

void writeUiLayout(const std::string& path, int width, int height, const std::vector<Ui::Rect>& rects) {
  nlohmann::ordered_json j;
  j["viewport"] = {width, height};
  j["windows"] = nlohmann::ordered_json::array();
  for (const Ui::Rect& r : rects)
    j["windows"].push_back({{"name", r.name}, {"x", r.x}, {"y", r.y}, {"w", r.w}, {"h", r.h}});
  std::ofstream out(path);
  out << j.dump(1) << '\n';
  if (!out.flush()) throw std::runtime_error("--ui-layout: cannot write " + path);
}

void Ui::render(bool draw) {
  // The lesson's own windows (a theory plot) in the layout too, so the layout tests see them.
  for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    const ImGuiWindowFlags skip = ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup;
    if (!w->Active || (w->Flags & skip) || std::string_view(w->Name).find("##") != std::string_view::npos) continue;
    if (std::none_of(layout_.begin(), layout_.end(), [&](const Rect& r) { return r.name == w->Name; }))
      layout_.push_back({w->Name, w->Pos.x, w->Pos.y, w->Size.x, w->Size.y});
  }
  ImGui::Render();
  if (draw) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool Ui::wantsMouse() const { return initialised_ && ImGui::GetIO().WantCaptureMouse; }
bool Ui::wantsKeyboard() const { return initialised_ && ImGui::GetIO().WantCaptureKeyboard; }

float collapsedWidth(const char* title) {
  return ImGui::CalcTextSize(title).x + ImGui::GetFrameHeight() + 3 * ImGui::GetStyle().WindowPadding.x;
}

namespace {

constexpr ImGuiWindowFlags kFixedPanel = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;

void errorLines(const std::vector<std::string>& errors, float wrap) {
  for (const auto& e : errors) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::PushTextWrapPos(std::min(wrap, ImGui::GetFontSize() * 50.0f));
    ImGui::TextUnformatted(e.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
  }
}

// The pass table: GPU and CPU ms per pass, or CPU ms alone on a software renderer.
void passTable(const std::vector<gl::PassTiming>& passes, bool softwareRenderer) {
  // A software renderer rasterises later, on its own threads: its timestamps bill next to nothing to
  // the pass that caused the work, so there the passes are timed on the CPU, synchronously.
  const bool noTimestamps = !gl::caps().timerQuery;  // WebGL2: no timer queries at all
  softwareRenderer = softwareRenderer || noTimestamps;
  const int columns = softwareRenderer ? 2 : 3;
  if (passes.empty() || !ImGui::BeginTable("passes", columns, ImGuiTableFlags_SizingFixedFit)) return;
  // The figure columns as wide as their widest content from the first frame on (an auto-fit one
  // takes a frame to widen, and a screenshot of frame 2 showed "skippe").
  const float figures = std::max(ImGui::CalcTextSize("skipped").x, ImGui::CalcTextSize("0000.00").x);
  ImGui::TableSetupColumn("pass");
  if (!softwareRenderer) ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed, figures);
  ImGui::TableSetupColumn("CPU ms", ImGuiTableColumnFlags_WidthFixed, figures);  // synchronous: what it cost
  ImGui::TableHeadersRow();
  for (const auto& p : passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (!p.drawn) {  // not drawn this frame (its map kept, its view off): its old mean is no cost now
      ImGui::TextDisabled("%s", p.name.c_str());
      for (int c = 1; c < columns; ++c) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("skipped");
      }
      continue;
    }
    ImGui::TextUnformatted(p.name.c_str());
    if (!softwareRenderer) {
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", p.gpuMs);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", p.cpuMs);
  }
  ImGui::EndTable();
  if (noTimestamps) ImGui::TextDisabled("WebGL2 has no timer queries: passes timed on the CPU");
  else if (softwareRenderer)
    ImGui::TextDisabled("software renderer: passes timed on the CPU (timestamps miss its work)");
}
}  // namespace

// The header: a few lines, so that the picture stays the picture (at a UI scale of 2 on 1280x720
// the old one with the pass table and every counter covered half the frame). The lesson names the
// figures that matter (LessonInfo::keyFigures); the rest is one key away, in the stats.
void Ui::panelOnly(const std::vector<std::string>& names, const ParamRegistry& params) {
  for (const std::string& n : names)
    if (!params.find(n)) throw ParamError("--panel: unknown parameter '" + n + "'; valid: " + params.names());
  only_ = names;
}

void Ui::header(const HeaderData& d) {
  if (!only_.empty()) return;  // --panel: the picture and the slide's knobs only
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(8 * scale_, 8 * scale_), ImGuiCond_Always);
  // At most the left 60 % and 60 % of the height: the panel takes the right, the picture the rest;
  // above a legend and the insets below it (the post-projective view's, at --ui-scale 2).
  const float maxWidth = vp->Size.x * kHeaderShare - 16 * scale_;
  const float maxHeight =
      std::max(roomAbove(8 * scale_, 8 * scale_ + maxWidth, std::min(vp->Size.y * 0.6f, legendTop_ - 16 * scale_)),
               3 * ImGui::GetFrameHeight());
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(maxWidth, maxHeight));
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: a see-through panel darkens the picture like a shadow
  ImGui::Begin("shadowlab", nullptr, kFixedPanel | ImGuiWindowFlags_NoTitleBar);  // its first line is the title
  // Lines longer than the header's width wrap instead of being cut off (a long figure, the title
  // at a UI scale of 2).
  const float wrap = maxWidth - ImGui::GetStyle().WindowPadding.x;
  ImGui::PushTextWrapPos(wrap);
  if (d.info) ImGui::Text("%s  %s", d.info->number.c_str(), d.info->title.c_str());
  ImGui::TextDisabled("%.1f ms  %.1f fps%s%s", d.frameMs, d.frameMs > 0 ? 1000.0 / d.frameMs : 0.0,
                      d.renderScale.empty() ? "" : "  ", d.renderScale.c_str());
  for (const auto& c : d.key) ImGui::Text("%s: %s", c.name.c_str(), c.value.c_str());
  errorLines(d.errors, wrap);
  if (!d.status.empty()) ImGui::TextDisabled("%s", d.status.c_str());
  ImGui::TextDisabled("F1 help  F2 stats  F3 parameters  H hide");
  ImGui::PopTextWrapPos();
  recordWindow("shadowlab");
  headerBottom_ = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
  ImGui::End();
}

void Ui::stats(const HeaderData& d, bool* open) {
  if (!only_.empty()) return;
  if (!*open) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = headerBottom_ + 4 * scale_;
  ImGui::SetNextWindowPos(ImVec2(8 * scale_, top), ImGuiCond_Always);
  const float maxWidth = vp->Size.x * kHeaderShare - 16 * scale_;
  const float bottom = std::min(vp->Size.y, legendTop_) - 8 * scale_;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                      ImVec2(maxWidth, std::max(bottom - top, 3 * ImGui::GetFrameHeight())));
  ImGui::SetNextWindowBgAlpha(1.0f);
  ImGui::Begin("Stats (F2)", open, kFixedPanel);
  const float wrap = maxWidth - ImGui::GetStyle().WindowPadding.x;
  ImGui::PushTextWrapPos(wrap);
  ImGui::TextDisabled("%s", d.gpu.c_str());
  if (d.passes) passTable(*d.passes, d.softwareRenderer);
  if (d.counters)
    for (const auto& c : *d.counters) ImGui::Text("%s: %s", c.name.c_str(), c.value.c_str());
  ImGui::PopTextWrapPos();
  recordWindow("Stats (F2)");
  ImGui::End();
}

void Ui::help(const LessonInfo& info, const ParamRegistry& params, bool* open) {
  if (!only_.empty()) return;
  if (!*open) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x * 0.5f, vp->Size.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  // Inside the frame (it scrolls), its long lines wrapped: at a UI scale of 2 they ran off its edge.
  const float maxWidth = vp->Size.x - 16 * scale_;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(maxWidth, vp->Size.y - 16 * scale_));
  ImGui::SetNextWindowBgAlpha(0.92f);
  ImGui::Begin("Help (F1)", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushTextWrapPos(maxWidth - ImGui::GetStyle().WindowPadding.x - ImGui::GetStyle().ScrollbarSize);
  ImGui::Text("%s  %s", info.number.c_str(), info.title.c_str());
  ImGui::TextUnformatted(info.summary.c_str());
  ImGui::Separator();
  ImGui::TextUnformatted(info.help.c_str());
  ImGui::Separator();
  ImGui::TextUnformatted(("Mouse: left drag orbit (fly: look), right drag pan, wheel zoom (fly: speed)\n" +
                          functionKeys("   ") + "   Esc quit")
                             .c_str());
  for (const FrameworkKey& k : frameworkKeys()) ImGui::Text("%-3s %s", k.key, k.action);
  bool any = false;
  for (const auto& p : params.params()) {
    if (p.hotkey.empty()) continue;
    if (!any) ImGui::Separator();
    any = true;
    ImGui::Text("%-3s %s  (%s)", p.hotkey.c_str(), p.name.c_str(), hotkeyAction(p).c_str());
  }
  ImGui::PopTextWrapPos();
  recordWindow("Help (F1)");
  ImGui::End();
}

void Ui::splitLabels(float divider, const std::string& a, const std::string& b) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  // Each label wrapped to its own half (a projector's UI scale makes a long key figure wider than
  // the half), both tops on one line as high as the taller needs, clear of the bottom.
  const float x = divider * size.x, gap = 16.0f;
  const float wrapA = std::max(x - gap - 8.0f, 40.0f), wrapB = std::max(size.x - x - gap - 8.0f, 40.0f);
  const ImVec2 ta = ImGui::CalcTextSize(a.c_str(), nullptr, false, wrapA);
  const ImVec2 tb = ImGui::CalcTextSize(b.c_str(), nullptr, false, wrapB);
  const float y = size.y - std::max(ta.y, tb.y) - ImGui::GetTextLineHeightWithSpacing() * 0.6f - 4.0f;
  auto label = [&](float left, const std::string& text, const ImVec2& t, float wrap, const char* name) {
    draw->AddRectFilled(ImVec2(left - 4, y - 4), ImVec2(left + t.x + 4, y + t.y + 4), IM_COL32(0, 0, 0, 180), 4.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(left, y), IM_COL32(255, 255, 255, 255), text.c_str(),
                  nullptr, wrap);
    layout_.push_back({name, left - 4, y - 4, t.x + 8, t.y + 8});
  };
  label(std::max(8.0f, x - ta.x - gap), a, ta, wrapA, "A label");
  label(x + gap, b, tb, wrapB, "B label");
  legendTop_ = std::min(legendTop_, y - 4.0f);  // the bottom-left stack (legend, exercises) stays above them
}

namespace {
ImVec4 stateColour(ExerciseState s) {
  switch (s) {
    case ExerciseState::Passing: return ImVec4(0.45f, 0.9f, 0.45f, 1.0f);
    case ExerciseState::Failing: return ImVec4(1.0f, 0.55f, 0.3f, 1.0f);
    case ExerciseState::Stub: return ImVec4(1.0f, 0.35f, 0.35f, 1.0f);
    default: return ImVec4(0.7f, 0.7f, 0.7f, 1.0f);
  }
}
}  // namespace

bool Ui::exercisesPanel(const Exercises& exercises) {
  if (!only_.empty()) return false;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // Bottom left, above a heatmap's legend when one is drawn (legends() runs first) and above the
  // insets the lesson reported under its column (reserve() runs first too).
  const float maxWidth = vp->Size.x * kHeaderShare - 16 * scale_;
  float bottom = std::min(vp->Size.y, legendTop_) - 8 * scale_;
  bottom = std::min(bottom, roomAbove(8 * scale_, 8 * scale_ + maxWidth, bottom + 8 * scale_) + 8 * scale_);
  ImGui::SetNextWindowPos(ImVec2(8 * scale_, bottom), ImGuiCond_Always, ImVec2(0, 1));
  // The header's share of the width at most (even collapsed it is as wide as its rows): the
  // parameter panel keeps the right.
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                      ImVec2(exercisesOpen_ ? maxWidth : collapsedWidth("Exercises"), vp->Size.y));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_Appearing);  // a title bar until opened: the picture stays visible
  bool rerun = false;
  const bool open =
      ImGui::Begin("Exercises", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  exercisesOpen_ = open;
  recordWindow("Exercises");
  legendTop_ = ImGui::GetWindowPos().y;  // the header stops above the bottom-left stack
  if (open) {
    for (const Exercise& e : exercises.list()) {
      ImGui::TextColored(stateColour(e.state), "%-5s %-8s", e.id.c_str(), exerciseStateName(e.state));
      ImGui::SameLine();
      ImGui::Text("%s%s  %d/%d", e.title.c_str(), e.glsl ? " [GLSL]" : "", e.passed, e.cases);
      if (ImGui::IsItemHovered() && !e.firstFailure.empty()) ImGui::SetTooltip("%s", e.firstFailure.c_str());
      if (e.markerLeft) ImGui::TextDisabled("      passing: delete its SHADOWLAB_STUB line");
    }
    ImGui::TextDisabled("public cases, run in this process; hover one for its first failure");
    rerun = ImGui::Button("run the cases again");
  }
  ImGui::End();
  return rerun;
}

void Ui::banner(const std::string& text) {
  if (text.empty()) return;
  // Bottom centre, above the exercises' title bar: the header and the parameters keep their place.
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x * 0.5f, vp->Size.y - 40 * scale_), ImGuiCond_Always, ImVec2(0.5f, 1));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.45f, 0.05f, 0.05f, 0.88f));
  ImGui::Begin("##stub banner", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoInputs);
  ImGui::PushTextWrapPos(vp->Size.x * 0.6f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  recordWindow("Stub banner");
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace shadowlab

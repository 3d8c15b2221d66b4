// The parameter panel (F3): the preset row and every parameter by group, or with --panel only the
// parameters a slide names (app/ui.hpp).
#include "app/ui.hpp"
#include "app/ui_layout.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "app/share.hpp"
#include "core/decimal.hpp"
#include "core/slider_style.hpp"

namespace shadowlab {

namespace {
// Shortest text that reads back as exactly `v`.
std::string exact(float v) { return shortestDecimal(v); }

std::string exact(const glm::vec3& v) { return exact(v.x) + " " + exact(v.y) + " " + exact(v.z); }

// One parameter's widget over a copy of its value: the new value as text when edited, else "".
std::string editWidget(const Param& p, const char* label) {
  switch (p.kind) {
    case ParamKind::Float: {
      float v = *static_cast<const float*>(p.target);
      const SliderStyle style = sliderStyle(p.min, p.max);
      const ImGuiSliderFlags flags = style.logarithmic ? ImGuiSliderFlags_Logarithmic : 0;
      return ImGui::SliderFloat(label, &v, p.min, p.max, style.format, flags) ? exact(v) : "";
    }
    case ParamKind::Int: {
      int v = *static_cast<const int*>(p.target);
      return ImGui::SliderInt(label, &v, int(p.min), int(p.max)) ? std::to_string(v) : "";
    }
    case ParamKind::Bool: {
      bool v = *static_cast<const bool*>(p.target);
      return ImGui::Checkbox(label, &v) ? (v ? "true" : "false") : "";
    }
    case ParamKind::Choice: {
      const int v = std::max(choiceIndex(p), 0);
      std::string picked;
      if (ImGui::BeginCombo(label, p.choices[std::size_t(v)].c_str())) {
        for (int i = 0; i < int(p.choices.size()); ++i)
          if (ImGui::Selectable(p.choices[std::size_t(i)].c_str(), i == v)) picked = p.choices[std::size_t(i)];
        ImGui::EndCombo();
      }
      return picked;
    }
    case ParamKind::Vec3: {
      glm::vec3 v = *static_cast<const glm::vec3*>(p.target);
      return ImGui::SliderFloat3(label, &v.x, p.min, p.max, sliderStyle(p.min, p.max).format) ? exact(v) : "";
    }
    case ParamKind::Color: {
      glm::vec3 v = *static_cast<const glm::vec3*>(p.target);
      return ImGui::ColorEdit3(label, &v.x) ? exact(v) : "";
    }
  }
  return "";
}
}  // namespace

namespace {
// A parameter's label in the panel: its name after the group (the part before the first dot).
const char* paramLabel(const std::string& name) {
  const auto dot = name.find('.');
  return name.c_str() + (dot == std::string::npos ? 0 : dot + 1);
}
}  // namespace

bool Ui::paramPanel(ParamRegistry& params, PresetFile& presets, const std::string& lesson, std::string& status,
                    bool* open) {
  bool changed = false;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x - 8 * scale_, 8 * scale_), ImGuiCond_Always, ImVec2(1, 0));
  // The right third at most, and never taller than the window: it scrolls (and collapses by its title).
  const float width = std::min(360 * scale_, vp->Size.x * (1.0f - kHeaderShare) - 8 * scale_);
  // Collapsed, no wider than its title: a bar in the corner, not a strip across the picture.
  ImGui::SetNextWindowSize(ImVec2(*open ? width : collapsedWidth("Parameters"), 0), ImGuiCond_Always);
  // Its bottom stays above the A/B split's labels (at most 3.6 lines from the bottom).
  const float labels = ImGui::GetTextLineHeightWithSpacing() * 4.2f;
  float maxHeight = vp->Size.y - 16 * scale_ - labels;
  const float left = vp->Size.x - 8 * scale_ - width;
  maxHeight = roomAbove(left, vp->Size.x, maxHeight);
  if (legendRect_.w > 0 && legendRect_.x < vp->Size.x && legendRect_.x + legendRect_.w > left)
    maxHeight = std::min(maxHeight, legendRect_.y - 16 * scale_);  // the legend (bottom right) stays visible
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                      ImVec2(vp->Size.x, std::max(maxHeight, 3 * ImGui::GetFrameHeight())));
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque, as the header
  // A title bar until opened (F3, or a click on it): the picture first.
  if (!panelSet_ || panelApplied_ != *open) ImGui::SetNextWindowCollapsed(!*open, ImGuiCond_Always);
  panelSet_ = true;
  ImGui::Begin("Parameters", nullptr, ImGuiWindowFlags_NoSavedSettings);
  const bool expanded = !ImGui::IsWindowCollapsed();
  *open = panelApplied_ = expanded;
  if (!expanded) {
    recordWindow("Parameters");
    ImGui::End();
    return false;
  }
  // Every widget as wide as the longest label leaves room for, but never under 45 % of the panel
  // (one long label would squeeze every value); a label still too long beside that narrows its own
  // widget, to a fifth of the panel at the least. ImGui's default (two thirds of the panel) cut
  // lesson 09's "plane_normal_offset" to "plane_normal_o".
  const float gap = ImGui::GetStyle().ItemInnerSpacing.x;
  float longest = 0;
  for (const Param& p : params.params())
    if (!p.hidden) longest = std::max(longest, ImGui::CalcTextSize(paramLabel(p.name)).x);
  const float room = ImGui::GetContentRegionAvail().x;
  const float common = std::max(0.45f * room, room - longest - gap);
  ImGui::PushItemWidth(common);
  float widest = 0;
  if (only_.empty()) {
    widest = presetRows(params, presets, lesson, status, room, changed);
    ImGui::Separator();
  }
  widest = std::max(widest, parameterRows(params, status, room, common, changed));
  ImGui::PopItemWidth();
  recordWindow("Parameters");
  // For the layout test: the widgets' right edge against the panel's visible content (a label
  // past it is cut off).
  const ImVec2 pos = ImGui::GetWindowPos();
  const float x0 = pos.x + ImGui::GetWindowContentRegionMin().x, x1 = pos.x + ImGui::GetWindowContentRegionMax().x;
  layout_.push_back({"Parameters content", x0, pos.y, x1 - x0, ImGui::GetWindowSize().y});
  layout_.push_back({"Parameters widgets", x0, pos.y, widest - x0, ImGui::GetWindowSize().y});
  ImGui::End();
  return changed;
}

// Presets: load one, or save the current state under a name; copy the view's link.
float Ui::presetRows(ParamRegistry& params, PresetFile& presets, const std::string& lesson, std::string& status,
                     float room, bool& changed) {
  const auto names = presets.names();
  if (ImGui::BeginCombo(
          "preset", presetIndex_ >= 0 && presetIndex_ < int(names.size()) ? names[presetIndex_].c_str() : "(choose)")) {
    for (int i = 0; i < int(names.size()); ++i) {
      if (ImGui::Selectable(names[i].c_str(), i == presetIndex_)) {
        presetIndex_ = i;
        try {
          presets.apply(names[i], params);
          status = "preset " + names[i];
        } catch (const ParamError& e) { status = e.what(); }
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  // The name field leaves room for the two buttons beside it, or takes the row and puts them
  // below it where the panel is too narrow for all three (a UI scale of 2 on 1280x720).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float buttons = ImGui::CalcTextSize("save preset").x + ImGui::CalcTextSize("defaults").x +
                        4 * style.FramePadding.x + 2 * style.ItemSpacing.x;
  const bool oneRow = room - buttons >= 0.4f * room;
  ImGui::SetNextItemWidth(oneRow ? room - buttons : room);
  ImGui::InputText("##name", presetName_, sizeof presetName_);
  float widest = ImGui::GetItemRectMax().x;  // the right edge of the widgets and their labels
  if (oneRow) ImGui::SameLine();
  if (ImGui::Button("save preset")) {
    try {
      presets.capture(presetName_, params);
      presets.save(presets.path);
      status = "saved preset '" + std::string(presetName_) + "' to " + presets.path;
    } catch (const ParamError& e) { status = e.what(); }
  }
  ImGui::SameLine();
  if (ImGui::Button("defaults")) {
    try {
      params.resetDefaults();
      changed = true;
    } catch (const ParamError& e) { status = e.what(); }
  }
  widest = std::max(widest, ImGui::GetItemRectMax().x);
  if (ImGui::Button(shareLabel())) status = shareView(params.changed(), lesson);
  return std::max(widest, ImGui::GetItemRectMax().x);
}

// Every visible parameter, ungrouped first, then each group under its header (collapsible).
float Ui::parameterRows(ParamRegistry& params, std::string& status, float room, float common, bool& changed) {
  const float gap = ImGui::GetStyle().ItemInnerSpacing.x;
  float widest = 0;
  std::string group;
  bool open = true;
  for (const Param* q : params.panelOrder()) {  // ungrouped first: none under another group's header
    const Param& p = *q;
    if (!only_.empty() && std::find(only_.begin(), only_.end(), p.name) == only_.end()) continue;
    const std::string g = only_.empty() ? ParamRegistry::groupOf(p.name) : "";  // --panel: no headers
    if (g != group) {
      group = g;
      open = g.empty() || ImGui::CollapsingHeader(g.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
    }
    if (!open) continue;
    const char* label = only_.empty() ? paramLabel(p.name) : p.name.c_str();  // --panel: no group headers
    ImGui::PushID(p.name.c_str());
    // The widget edits a copy; the registry takes it (range and checks) or refuses it, keeping
    // the last good value and saying why in the header.
    const float own = room - ImGui::CalcTextSize(label).x - gap;
    if (own < common) ImGui::PushItemWidth(std::max(0.2f * room, own));
    const std::string edit = editWidget(p, label);
    if (own < common) ImGui::PopItemWidth();
    widest = std::max(widest, ImGui::GetItemRectMax().x);
    if (ImGui::IsItemHovered() && !p.why.empty())
      ImGui::SetTooltip("%s%s%s", p.why.c_str(), p.hotkey.empty() ? "" : "\nhotkey: ", p.hotkey.c_str());
    if (!edit.empty()) {
      try {
        params.set(p.name, edit);
        changed = true;
      } catch (const ParamError& e) { status = std::string("refused: ") + e.what() + "; kept " + params.get(p.name); }
    }
    ImGui::PopID();
  }
  return widest;
}

}  // namespace shadowlab

#include "soft_theory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName: where the framework's windows are this frame

namespace shadowlab::tech {

std::vector<DebugDraw::Line> penumbraLines(const glm::vec3& a, const glm::vec3& b,
                                           const std::vector<soft::PenumbraEdgeSample>& s) {
  const glm::vec4 white{1, 1, 1, 1}, yellow{1, 0.9f, 0.2f, 1}, red{1, 0.25f, 0.2f, 1}, cyan{0.2f, 0.9f, 1, 1};
  std::vector<DebugDraw::Line> lines = {{a, b, white}};
  const glm::vec3 lift(0, 0.01f, 0);  // a centimetre above the receiver, so the lines are not in it
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (k + 1 < s.size()) {
      lines.push_back({s[k].centre + lift, s[k + 1].centre + lift, yellow});
      lines.push_back({s[k].inner + lift, s[k + 1].inner + lift, red});
      lines.push_back({s[k].outer + lift, s[k + 1].outer + lift, cyan});
    }
    if (k % 4 == 0 || k + 1 == s.size()) lines.push_back({s[k].inner + lift, s[k].outer + lift, yellow});
  }
  return lines;
}

PlotFigures compareFractions(const FractionFn& exact, const FractionFn& linear) {
  PlotFigures f;
  for (int i = 0; i <= 1000; ++i) {
    const float t = -1.0f + 2.0f * float(i) / 1000.0f;
    const float d = std::abs(exact(t) - linear(t));
    if (d > f.maxDifference) f = {d, t};
  }
  return f;
}

void visibleFractionPlot(const FractionFn& exact, const FractionFn& linear) {
  const float em = ImGui::GetFontSize();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Bottom left, in the band between the framework's header and what sits below it (the exercises
  // panel, a heatmap's legend; all drawn before the lesson's UI this frame), 14 lines tall at most:
  // at a fixed 14 lines it covered the exercises panel, and at a UI scale of 2 on 1280x720 the
  // header too.
  float top = em, bottom = display.y - em;
  auto active = [](const char* name) {
    const ImGuiWindow* w = ImGui::FindWindowByName(name);
    return w && w->Active ? w : nullptr;
  };
  if (const ImGuiWindow* h = active("shadowlab")) top = h->Pos.y + h->Size.y + 0.5f * em;
  for (const char* below : {"Exercises", "Legend"})
    if (const ImGuiWindow* w = active(below)) bottom = std::min(bottom, w->Pos.y - 0.5f * em);
  const float height = std::clamp(bottom - top, 6.0f * em, 14.0f * em);
  ImGui::SetNextWindowPos(ImVec2(em, bottom - height), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(22.0f * em, height), ImGuiCond_Always);
  if (!ImGui::Begin("A_frac, the visible fraction", nullptr, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  const PlotFigures f = compareFractions(exact, linear);
  ImGui::Text("max |difference| %.2f %% at a/R %+.2f", 100.0f * f.maxDifference, f.at);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  // The graph takes what the key line below it leaves, 2.5 lines at the least (no scrollbar: the
  // graph follows the window).
  const float keyLine = ImGui::GetStyle().ItemSpacing.y + ImGui::GetTextLineHeight();
  const ImVec2 size(ImGui::GetContentRegionAvail().x, std::max(ImGui::GetContentRegionAvail().y - keyLine, 2.5f * em));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(120, 120, 120, 255));
  auto at = [&](float t, float v) {
    return ImVec2(origin.x + 0.5f * (t + 1.0f) * size.x, origin.y + (1.0f - v) * size.y);
  };
  const struct {
    const FractionFn& f;
    ImU32 colour;
  } curves[] = {{exact, IM_COL32(255, 220, 60, 255)}, {linear, IM_COL32(60, 200, 255, 255)}};
  for (const auto& c : curves)
    for (int i = 0; i < 64; ++i) {
      const float t0 = -1.0f + 2.0f * float(i) / 64.0f, t1 = -1.0f + 2.0f * float(i + 1) / 64.0f;
      draw->AddLine(at(t0, c.f(t0)), at(t1, c.f(t1)), c.colour, 2.0f);
    }
  // The difference, ten times enlarged, around the middle line.
  for (int i = 0; i < 64; ++i) {
    const float t0 = -1.0f + 2.0f * float(i) / 64.0f, t1 = -1.0f + 2.0f * float(i + 1) / 64.0f;
    draw->AddLine(at(t0, 0.5f + 10.0f * (exact(t0) - linear(t0))), at(t1, 0.5f + 10.0f * (exact(t1) - linear(t1))),
                  IM_COL32(255, 90, 90, 255), 1.0f);
  }
  draw->AddLine(at(f.at, 0.0f), at(f.at, 1.0f), IM_COL32(255, 90, 90, 120));
  ImGui::Dummy(size);
  ImGui::TextColored(ImVec4(1, 0.86f, 0.24f, 1), "A_frac");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(0.24f, 0.78f, 1, 1), "(1 + a/R) / 2");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(1, 0.35f, 0.35f, 1), "difference x10");
  ImGui::End();
}

}  // namespace shadowlab::tech

// "copy link" natively: the command line that opens the view, to the clipboard (share.hpp).
#include "app/share.hpp"

#include <imgui.h>

#include "core/cli.hpp"

namespace shadowlab {

const char* shareLabel() { return "copy command"; }

std::string shareView(const ParamValues& changed, const std::string& lesson) {
  const std::string line = viewCommandLine("build/default/bin/lesson_" + lesson, changed);
  ImGui::SetClipboardText(line.c_str());
  return changed.empty() ? "copied (every parameter at its default): " + line : "copied: " + line;
}

}  // namespace shadowlab

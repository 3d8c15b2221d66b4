#pragma once
// "copy link" in the parameter panel: the view on screen (every parameter changed from its default,
// the camera's pose included) as something to send a student or to paste into the slides' notes.
// Natively the command line that opens it (core/cli viewCommandLine), to the clipboard; in the
// browser (share_web.cpp) the page's URL (?set=name=value&...), in the address bar and the clipboard.
#include <string>

#include "core/params.hpp"

namespace shadowlab {

// The button's label on this platform.
const char* shareLabel();
// Copies the view of `lesson` ("03_shadow_quality") with these values; returns the status line that
// says what was copied.
std::string shareView(const ParamValues& changed, const std::string& lesson);

}  // namespace shadowlab

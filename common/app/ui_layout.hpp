#pragma once
// What the UI's windows share about the frame's layout (app/ui.cpp, app/ui_panel.cpp).
namespace shadowlab {

// The header's share of the width from the left; the parameter panel gets the rest, at the right.
inline constexpr float kHeaderShare = 0.6f;

// A collapsed window's width: its arrow, its title and the padding.
float collapsedWidth(const char* title);

}  // namespace shadowlab

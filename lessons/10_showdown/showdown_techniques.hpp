#pragma once
// The showdown's techniques, in the order of its `technique` choice: the hard ones of lessons 03,
// 08, 09, 10, 07 and 04, lesson 05's soft ones, and none. Each is held under its own name
// (uniform.map_size, csm.cascades, pcss.filter_taps) and shown by the preset its entry names.
// Adding a technique to the showdown: its files (docs/adding_a_technique.md) and one entry here.
#include <vector>

#include "technique/registry.hpp"

namespace shadowlab::tech {

std::vector<TechniqueEntry> showdownTechniques();

}  // namespace shadowlab::tech

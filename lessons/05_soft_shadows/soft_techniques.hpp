#pragma once
// Lesson 05's techniques, in the order of its `technique` choice: each an approximation of the
// sphere light's visible fraction, each measured against the Embree sphere-light reference. The
// showdown holds them all beside the hard ones (lessons/10_showdown/showdown_techniques).
#include <vector>

#include "technique/registry.hpp"

namespace shadowlab::tech {

std::vector<TechniqueEntry> softTechniques();

}  // namespace shadowlab::tech

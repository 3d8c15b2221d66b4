#version 410 core
// The depth pass, fragment: no colour is written, only depth, after the caster's alpha test
// (common/caster_alpha.glsl; none at all for an opaque caster).
#include "common/caster_alpha.glsl"

void main() { casterAlphaTest(); }

#version 410 core
// Deliberately invalid through an include: shader_check must blame include/broken_helper.glsl:3.
#include "include/broken_helper.glsl"

out vec4 fragColor;
void main() { fragColor = vec4(brokenHelper()); }

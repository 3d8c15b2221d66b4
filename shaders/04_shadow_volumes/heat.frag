#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), the stencil view: a full-
// screen triangle per count, drawn where the stencil equals that count (glStencilFunc EQUAL), so
// the stencil buffer shows as a heatmap without reading it.
#include "common/measure.glsl"
uniform vec4 uColor;
layout(location = 0) out vec4 fragColor;
void main() {
  fragColor = uColor;
  writeNoMeasurement();
}

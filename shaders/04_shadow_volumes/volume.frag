#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04): the shadow volume's faces.
// While counting, colour writes are off and only the stencil changes; the volumes and wireframe
// views draw them in uColor.
#include "common/measure.glsl"
uniform vec4 uColor;
layout(location = 0) out vec4 fragColor;
void main() {
  fragColor = gl_FrontFacing ? uColor : vec4(uColor.rgb * 0.6, uColor.a);
  writeNoMeasurement();
}

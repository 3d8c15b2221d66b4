#version 410 core
#include "common/measure.glsl"
in vec4 gColor;
layout(location = 0) out vec4 fragColor;
void main() {
  fragColor = gColor;
  writeNoMeasurement();
}

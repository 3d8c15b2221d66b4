#version 410 core
#include "common/measure.glsl"
in vec4 gColor;
out vec4 fragColor;
void main() {
  fragColor = gColor;
  writeNoMeasurement();
}

#version 410 core
#include "common/measure.glsl"
in vec4 vColor;
out vec4 fragColor;
void main() {
  fragColor = vColor;
  writeNoMeasurement();
}

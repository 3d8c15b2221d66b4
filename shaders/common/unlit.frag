#version 410 core
#include "common/measure.glsl"
uniform vec4 uColor;
layout(location = 0) out vec4 fragColor;
void main() {
  fragColor = uColor;
  writeNoMeasurement();  // gizmos are not surfaces the ground truth should judge
}

#version 410 core
// The layers of a projective map set side by side (lessons/08_psm/projective_maps, view=map):
// raw window depth, stretched so that the far end of a perspective map is not all white.
#include "common/measure.glsl"

in vec2 vUv;
uniform sampler2DArray uLayers;  // through a raw (non-comparing) sampler
uniform int uCount;
layout(location = 0) out vec4 fragColor;

void main() {
  float x = vUv.x * float(uCount);
  int k = min(int(x), uCount - 1);
  float d = texture(uLayers, vec3(fract(x), vUv.y, float(k))).r;
  float shade = d >= 1.0 ? 1.0 : pow(d, 16.0);
  bool border = fract(x) < 0.004 && k > 0;
  fragColor = vec4(border ? vec3(1.0, 0.6, 0.2) : vec3(shade), 1.0);
  writeNoMeasurement();
}

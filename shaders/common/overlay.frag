#version 410 core
#include "common/measure.glsl"
// Blends a heatmap over the frame (measurement overlays). Transparent texels leave the frame alone.
in vec2 vUv;
uniform sampler2D uOverlay;
uniform float uOpacity;
uniform int uFlip;  // 1: the image's first row is the top of the screen
layout(location = 0) out vec4 fragColor;
void main() {
  vec4 c = texture(uOverlay, uFlip == 1 ? vec2(vUv.x, 1.0 - vUv.y) : vUv);
  fragColor = vec4(c.rgb, c.a * uOpacity);
  writeNoMeasurement();
}

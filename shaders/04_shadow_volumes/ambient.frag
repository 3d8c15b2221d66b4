#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), pass 1: depth and ambient.
// Lays down the depth every later pass tests against and the light that reaches everywhere (ka Ia).
// For the measurement it writes V = 0 for every surface: the measured light's lit pass overwrites
// it with 1 where the stencil count is 0.
#include "common/lighting.glsl"
#include "common/measure.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform vec3 uEye;
uniform vec3 uAmbient;     // ka Ia
uniform vec3 uAlbedo;      // kd
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform bool uTwoSided;

layout(location = 0) out vec4 fragColor;

void main() {
  vec3 N = normalize(vNormal);
  if (uTwoSided && dot(N, uEye - vWorldPos) < 0.0) N = -N;
  writeMeasurement(vWorldPos, N, 0.0, vec2(0.0));
  vec3 kd = uAlbedo;
  if (uUseTexture) kd *= texture(uTexture, vUv).rgb;
  fragColor = vec4(toDisplay(uAmbient * kd), 1.0);
}

#version 410 core
// The hybrid map's views on the scene (lessons/07_hybrid_maps/hybrid_maps: drawSceneView), drawn instead
// of the lit pass and linked with shadow_hybrid.frag: each pixel coloured by the level its lookup
// of light uViewLight reached (uSceneView 0: the merge mask), or by the
// steps it took down the index (1: a heatmap, 0 blue .. 3 red); brighter where lit. Outside the
// map: grey. Measured like the lit pass (the same V).
#include "common/light.glsl"
#include "common/measure.glsl"
#include "07_hybrid_maps/colours.glsl"

float hybridVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords, out int level, out int steps);

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform int uLightCount;
uniform vec3 uEye;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform float uAlphaCutoff;
uniform bool uTwoSided;
uniform int uSceneView;  // 0 levels, 1 steps
uniform int uViewLight;  // -1: none has a map (everything grey)

layout(location = 0) out vec4 fragColor;

void main() {
  vec3 N = normalize(vNormal);
  if (uTwoSided && dot(N, uEye - vWorldPos) < 0.0) N = -N;
  vec2 texelCoords = vec2(0.0);
  int level = -1, steps = 0;
  float v = hybridVisibility(max(uViewLight, 0), vWorldPos, N, texelCoords, level, steps);
  if (uViewLight < 0) level = -1;
  vec4 texel = uUseTexture ? texture(uTexture, vUv) : vec4(1.0);
#ifndef DEPTH_PREPASS  // (after LitPass's depth pre-pass a hole's fragment fails the EQUAL test)
  if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;
#endif
  writeMeasurement(vWorldPos, N, v, texelCoords);
  vec3 colour = level < 0 ? vec3(0.55) : uSceneView == 0 ? HYBRID_LEVEL_COLOURS[level] : HYBRID_STEP_COLOURS[steps];
  fragColor = vec4(colour * (0.4 + 0.6 * v), 1.0);
}

#version 410 core
// The lit pass every map technique serves (common/technique/lit_pass): the lecture's model
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (N.H_i)^pow]   (seeds 004, Blinn's highlight)
// with V_i from the technique, whichever it is: its own fragment shader, linked into this program,
// defines shadowVisibility (shaders/common/shadow_*.frag). One shader for any technique and any
// number of lights (up to MAX_LIGHTS).
#include "common/lighting.glsl"
#include "common/measure.glsl"

// V of light `light` at the surface point (worldPos, unit normal N), in [0, 1]; texelCoords: the
// shadow-map texel coordinates there (uv * size) for the aliasing measurement, vec2(0) without a map.
float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords);

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform Light uLights[MAX_LIGHTS];
uniform int uLightCount;
uniform vec3 uEye;
uniform vec3 uAmbient;
uniform vec3 uAlbedo;
uniform float uSpecular, uShininess;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform float uAlphaCutoff;
uniform bool uTwoSided;
uniform int uView;  // 0 lit, 1 the visibility of the measured light (light 0 when none is measured)

out vec4 fragColor;

void main() {
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;
  // V first, in uniform control flow: techniques take screen-space derivatives (receiver plane,
  // texel coordinates for the aliasing measurement) that a discard before them would spoil.
  float vis[MAX_LIGHTS];
  vec2 texelCoords[MAX_LIGHTS];
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    vis[i] = 1.0;
    texelCoords[i] = vec2(0.0);
  }
  for (int i = 0; i < uLightCount; ++i) vis[i] = shadowVisibility(i, vWorldPos, N, texelCoords[i]);

  vec4 texel = uUseTexture ? texture(uTexture, vUv) : vec4(1.0);
  if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;  // the holes of leaf cards and fences

  int m = clamp(uMeasureLight, 0, max(uLightCount - 1, 0));
  writeMeasurement(vWorldPos, N, vis[m], texelCoords[m]);
  if (uView == 1) {
    fragColor = vec4(vec3(vis[uMeasureLight >= 0 ? m : 0]), 1.0);
    return;
  }
  vec3 kd = uAlbedo * texel.rgb;
  vec3 color = uAmbient * kd;
  for (int i = 0; i < uLightCount; ++i)
    color += lightContribution(N, toLight(uLights[i], vWorldPos), V, incidentRadiance(uLights[i], vWorldPos), vis[i],
                               kd, uSpecular, uShininess, true);
  fragColor = vec4(toDisplay(color), 1.0);
}

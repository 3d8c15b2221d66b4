#version 410 core
// The lit pass every map technique serves (common/technique/lit_pass): the lecture's model
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (N.H_i)^pow]   ([Tarantsev-L12], Blinn's highlight)
// with V_i from the technique, whichever it is: its own fragment shader, linked into this program,
// defines shadowVisibility (shaders/common/shadow_*.frag). One shader for any technique and any
// number of lights (up to MAX_LIGHTS).
//
// Specialised (common/technique/lit_pass): LitPass compiles a variant per light set with
//   LIGHT_COUNT n   LIGHT_ON a, b, c, d (1 on, 0 off)   LIGHT_KINDS k0, k1, k2, k3   VIEW v
// so that each light's switch and kind are constants and the lights that are off cost nothing
// (docs/performance.md, "Constants, not uniforms"). Without the defines (the generic variant, drawn
// while a specialised one compiles) the same code runs on the uniforms.
#include "common/lighting.glsl"
#include "common/measure.glsl"

// V of light `light` at the surface point (worldPos, unit normal N), in [0, 1]; texelCoords: the
// shadow-map texel coordinates there (uv * size) for the aliasing measurement, vec2(0) without a map.
float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords);
#ifdef SHADOW_TEXEL_JACOBIAN
// A technique that defines SHADOW_TEXEL_JACOBIAN gives the aliasing measurement its own Jacobian of
// texel coordinates per screen pixel, from the surface point's screen-space steps (the cascades:
// through the pixel's own cascade, where dFdx of texelCoords would span two maps at a seam). Used
// in measured frames only (MEASURED_FRAME, LitPass): elsewhere nothing reads it.
vec4 shadowTexelJacobian(int light, vec3 worldPos, vec3 dPdx, vec3 dPdy);
#endif

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
#include "common/two_sided.glsl"
uniform int uView;  // 0 lit, 1 the visibility of the measured light (light 0 when none is measured)

layout(location = 0) out vec4 fragColor;

#ifdef LIGHT_COUNT
const bool kLightOn[MAX_LIGHTS] = bool[](LIGHT_ON);
const int kLightKind[MAX_LIGHTS] = int[](LIGHT_KINDS);
#define LIGHTS LIGHT_COUNT
#define LIGHT_IS_ON(i) kLightOn[i]
#define SCENE_VIEW VIEW
// Light i with its kind as a constant: the branches on the kind fold away.
Light sceneLight(int i) {
  Light l = uLights[i];
  l.kind = kLightKind[i];
  l.enabled = true;
  return l;
}
#else
#define LIGHTS MAX_LIGHTS
#define LIGHT_IS_ON(i) (i < uLightCount)
#define SCENE_VIEW uView
Light sceneLight(int i) { return uLights[i]; }
#endif

// V_i of light i (1 for a light that is off), and the texel coordinates the measurement reads.
float visibility(int i, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (i < LIGHTS && LIGHT_IS_ON(i)) return shadowVisibility(i, vWorldPos, N, texelCoords);
  return 1.0;
}

// Light i's term of the sum: V_i f_att,i I_i [kd (N.L_i) + ks (N.H_i)^pow] (nothing for a light that is off).
vec3 shade(int i, vec3 N, vec3 V, vec3 kd, float v) {
  if (!(i < LIGHTS && LIGHT_IS_ON(i))) return vec3(0.0);
  Light light = sceneLight(i);
  return lightContribution(N, toLight(light, vWorldPos), V, incidentRadiance(light, vWorldPos), v, kd,
                           uSpecular, uShininess, true);
}

void main() {
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;
  // V first, in uniform control flow: techniques take screen-space derivatives (receiver plane,
  // texel coordinates for the aliasing measurement) that a discard before them would spoil.
  // One call per light, each index a literal, not a loop (docs/performance.md, "A constant light
  // index"): a technique picks each light's map with a switch on the index, which then folds away.
  float vis[MAX_LIGHTS];
  vec2 texelCoords[MAX_LIGHTS];
  vis[0] = visibility(0, N, texelCoords[0]);
  vis[1] = visibility(1, N, texelCoords[1]);
  vis[2] = visibility(2, N, texelCoords[2]);
  vis[3] = visibility(3, N, texelCoords[3]);
#if defined(SHADOW_TEXEL_JACOBIAN) && defined(MEASURED_FRAME)
  vec3 dPdx = dFdx(vWorldPos), dPdy = dFdy(vWorldPos);  // before the discard below
#endif

  vec4 texel = uUseTexture ? texture(uTexture, vUv) : vec4(1.0);
#ifndef DEPTH_PREPASS  // (after a depth pre-pass a hole's fragment fails the EQUAL test: no discard)
  if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;  // the holes of leaf cards and fences
#endif

  int m = clamp(uMeasureLight, 0, max(LIGHTS - 1, 0));
#if defined(SHADOW_TEXEL_JACOBIAN) && defined(MEASURED_FRAME)
  writeMeasurementJacobian(vWorldPos, N, vis[m], shadowTexelJacobian(m, vWorldPos, dPdx, dPdy));
#else
  writeMeasurement(vWorldPos, N, vis[m], texelCoords[m]);
#endif
  if (SCENE_VIEW == 1) {
    fragColor = vec4(vec3(vis[uMeasureLight >= 0 ? m : 0]), 1.0);
    return;
  }
  vec3 kd = uAlbedo * texel.rgb;
  vec3 color = uAmbient * kd;
  color += shade(0, N, V, kd, vis[0]);  // a literal index each, as above
  color += shade(1, N, V, kd, vis[1]);
  color += shade(2, N, V, kd, vis[2]);
  color += shade(3, N, V, kd, vis[3]);
  fragColor = vec4(toDisplay(color), 1.0);
}

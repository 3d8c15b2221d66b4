#version 410 core
// The lit pass every map technique serves (common/technique/lit_pass): the lecture's model
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (N.H_i)^pow]   ([Tarantsev-L12], Blinn's highlight)
// with V_i from the technique, whichever it is: its own fragment shader, linked into this program,
// defines shadowVisibility (shaders/common/shadow_*.frag). One shader for any technique and any
// number of lights (up to MAX_LIGHTS).
//
// Specialised (common/technique/lit_pass): a software renderer pays for every light the shader
// visits, even one a uniform switches off, so LitPass compiles a variant per light set with
//   LIGHT_COUNT n   LIGHT_ON a, b, c, d (1 on, 0 off)   LIGHT_KINDS k0, k1, k2, k3   VIEW v
// and the per-light code (VISIBILITY, SHADE: a constant index each) folds to the lights that are
// on, each of its kind. Without the defines (the generic variant, drawn while a specialised one
// compiles) the same code runs on the uniforms.
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
uniform bool uTwoSided;
uniform int uView;  // 0 lit, 1 the visibility of the measured light (light 0 when none is measured)

out vec4 fragColor;

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
// Every light's index is a constant here too (VISIBILITY, SHADE), and so is the technique's sampler
// for it: a sampler array indexed by a variable costs a software renderer dearly.
#define LIGHTS MAX_LIGHTS
#define LIGHT_IS_ON(i) (i < uLightCount)
#define SCENE_VIEW uView
Light sceneLight(int i) { return uLights[i]; }
#endif

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
  // Written out per light, so every index is a constant whether or not the compiler unrolls.
  // (one line: GLSL ES-style validators reject a backslash line continuation)
#define VISIBILITY(i) if (i < LIGHTS && LIGHT_IS_ON(i)) vis[i] = shadowVisibility(i, vWorldPos, N, texelCoords[i]);
  VISIBILITY(0) VISIBILITY(1) VISIBILITY(2) VISIBILITY(3)
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
  // Written out per light with a constant index, as VISIBILITY above: each light's switch and kind
  // are then constants that fold away. The same as a loop with `continue` over the lights, which
  // llvmpipe ran slower (lesson 03's default scene pass 57-69 -> 43-57 ms, the picture unchanged).
#define SHADE(i) if (i < LIGHTS && LIGHT_IS_ON(i)) { Light light = sceneLight(i); color += lightContribution(N, toLight(light, vWorldPos), V, incidentRadiance(light, vWorldPos), vis[i], kd, uSpecular, uShininess, true); }
  SHADE(0) SHADE(1) SHADE(2) SHADE(3)
  fragColor = vec4(toDisplay(color), 1.0);
}

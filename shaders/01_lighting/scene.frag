#version 410 core
#include "common/lighting.glsl"
#include "common/measure.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec3 vColor;
in vec4 vClip;

uniform Light uLights[MAX_LIGHTS];
uniform int uLightCount;
uniform vec3 uEye;
uniform vec3 uAmbient;        // ka Ia
uniform vec3 uAlbedo;         // kd
uniform float uSpecular;      // ks
uniform float uShininess;     // pow
uniform bool uBlinn;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform bool uTwoSided;
uniform int uView;            // 0 lit, 1 normals, 2 albedo, 3 ndc remap, 4 vertex colour (CPU)
uniform mat4 uNdcToTexture;   // exercise 01.2, used by the ndc view

layout(location = 0) out vec4 fragColor;

// Specialised by the lesson (a variant per set): LIGHT_COUNT n, LIGHT_KINDS k0, k1, k2, k3, VIEW v,
// BLINN 0|1. A software renderer pays for every branch a uniform would switch, so the program is
// compiled for the lights and the view in use; without the defines it runs on the uniforms.
#ifdef LIGHT_COUNT
const int kLightKind[MAX_LIGHTS] = int[](LIGHT_KINDS);
#define LIGHTS LIGHT_COUNT
#define LIGHT_KIND(i) kLightKind[i]
#else
#define LIGHTS uLightCount
#define LIGHT_KIND(i) uLights[i].kind
#endif
#ifndef VIEW
#define VIEW uView
#endif
#ifndef BLINN
#define BLINN uBlinn
#endif

void main() {
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;  // leaf cards are lit from the side we see
  // For the ground-truth comparison: this pixel's point, normal and V of the measured light (1:
  // lesson 01 lights everything that faces a light). No shadow map, so no texel Jacobian.
  writeMeasurement(vWorldPos, N, 1.0, vec2(0.0));
  vec3 kd = uAlbedo;
  if (uUseTexture) kd *= texture(uTexture, vUv).rgb;  // "modulate": texture times material

  if (VIEW == 1) { fragColor = vec4(N * 0.5 + 0.5, 1.0); return; }
  if (VIEW == 2) { fragColor = vec4(toDisplay(kd), 1.0); return; }
  if (VIEW == 3) { fragColor = vec4((uNdcToTexture * vec4(vClip.xyz / vClip.w, 1.0)).xyz, 1.0); return; }
  if (VIEW == 4) { fragColor = vec4(toDisplay(vColor * (uUseTexture ? texture(uTexture, vUv).rgb : vec3(1.0))), 1.0); return; }

  // ---- the illumination model, V_i = 1 for every light (lesson 01: no shadows yet) ----
  vec3 color = uAmbient * kd;
  for (int i = 0; i < LIGHTS; ++i) {
    Light light = uLights[i];
    light.kind = LIGHT_KIND(i);
    vec3 L = toLight(light, vWorldPos);
    float visibility = 1.0;  // V_i: the rest of the course is about computing this
    color += lightContribution(N, L, V, incidentRadiance(light, vWorldPos), visibility, kd, uSpecular, uShininess,
                               bool(BLINN));
  }
  fragColor = vec4(toDisplay(color), 1.0);
}

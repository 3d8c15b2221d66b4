#version 410 core
// Pass 2, fragment: the lecture's model with V from the shadow map ([Boreskov2005], [Tarantsev-L12]).
#include "common/lighting.glsl"
#include "common/measure.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadow;
in float vCpuVisibility;

uniform Light uLight;
uniform vec3 uEye;
uniform vec3 uAmbient;
uniform vec3 uAlbedo;
uniform float uSpecular, uShininess;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform float uAlphaCutoff;
uniform bool uTwoSided;

uniform sampler2DShadow uShadowMap;  // compare mode R-to-texture, LEQUAL (ARB_shadow)
uniform sampler2D uShadowDepth;      // the same texture, no comparison
uniform int uCompare;                // 0 hardware, 1 manual in the shader, 2 CPU per vertex, 3 off
uniform float uBias;                 // in-shader constant bias, in texture depth units
uniform float uMapSize;
uniform int uView;                   // 0 lit, 1 visibility, 2 light-space depth

layout(location = 0) out vec4 fragColor;

// Specialised by the lesson: COMPARE c and VIEW v as constants (a software renderer pays for every
// branch a uniform would switch); without them the same code reads the uniforms.
#ifndef COMPARE
#define COMPARE uCompare
#endif
#ifndef VIEW
#define VIEW uView
#endif

// compare=manual: the lookup and comparison written in the shader, exercises 02.4 and 02.5 (yours
// with impl=student; the reference's is withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_GLSL
#include "exercises.glsl"
#else
#include "exercises_reference.glsl"
#endif

float shadowVisibility(vec4 s) {
  if (COMPARE == 2) return vCpuVisibility;
  if (COMPARE == 3) return 1.0;
  if (COMPARE == 1) return shadowLookup(uShadowDepth, s, uBias);
  if (s.w <= 0.0) return 1.0;       // behind the light: the spot cone is zero there
  if (s.z / s.w > 1.0) return 1.0;  // beyond the light's far plane: nothing known
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: outside the map is lit, as the sampler's border says natively
  if (s.xy != clamp(s.xy, vec2(0.0), s.ww)) return 1.0;
#endif
  return textureProj(uShadowMap, vec4(s.xy, s.z - uBias * s.w, s.w));
}

void main() {
  vec4 texel = uUseTexture ? texture(uTexture, vUv) : vec4(1.0);
#ifndef DEPTH_PREPASS  // after the pre-pass a hole's fragment fails the depth test EQUAL: nothing to discard
  if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;  // the holes of leaf cards and fences
#endif
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;
  float visibility = shadowVisibility(vShadow);
  vec2 uv = vShadow.w > 0.0 ? vShadow.xy / vShadow.w : vec2(0.0);
  writeMeasurement(vWorldPos, N, visibility, uv * uMapSize);

  if (VIEW == 1) { fragColor = vec4(vec3(visibility), 1.0); return; }
  if (VIEW == 2) { fragColor = vec4(vec3(vShadow.w > 0.0 ? vShadow.z / vShadow.w : 1.0), 1.0); return; }
  vec3 kd = uAlbedo * texel.rgb;
  vec3 L = toLight(uLight, vWorldPos);
  vec3 color = uAmbient * kd + lightContribution(N, L, V, incidentRadiance(uLight, vWorldPos), visibility, kd,
                                                 uSpecular, uShininess, true);
  fragColor = vec4(toDisplay(color), 1.0);
}

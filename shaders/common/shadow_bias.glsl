// The bias family of every 2D shadow map (shadow_uniform.frag, shadow_hybrid.frag): the slope-scaled
// depth bias and the normal-offset lookup point. Mirrors common/algorithms/shadow_math; keep the two
// in step. Needs common/light.glsl.
uniform float uConstantBias;  // depth units
uniform float uSlopeBias;     // depth units per unit of tan(theta)
uniform float uMaxBias;
uniform float uNormalOffset;  // texels of world offset along the normal

// float slopeScaledBias(float cosTheta): min(constant + slope * tan(theta), max), the max when
// cosTheta <= 0: exercise 03.1 in GLSL, sealed in the student handout.
#include "common/shadow_bias_slope.glsl"

// Normal offset: the lookup point moves along the normal by a few texels' world size (`texel`: an
// orthographic map's world texel; a perspective map's texel at unit distance, times the distance),
// scaled by sin(theta): nothing head-on, most at grazing light. cosTheta = N.L comes back for the bias.
vec3 normalOffsetPoint(Light light, bool perspective, float texel, vec3 worldPos, vec3 N, out float cosTheta) {
  if (!perspective) {
    cosTheta = dot(N, -light.direction);
    return worldPos + N * uNormalOffset * texel * sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  }
  vec3 toLightPos = light.position - worldPos;
  cosTheta = dot(N, normalize(toLightPos));
  return worldPos + N * uNormalOffset * texel * length(toLightPos) * sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
}

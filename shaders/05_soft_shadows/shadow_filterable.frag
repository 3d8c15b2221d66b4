#version 410 core
// Filterable shadow maps (lessons/05_soft_shadows/filterable_maps; lesson 05), blurred once per frame and
// read with one bilinear lookup, from the sphere's centre camera (soft_maps.glsl):
//   VSM  Chebyshev's one-sided bound p = s^2 / (s^2 + (t - mu)^2) for t > mu, an upper bound of
//        the lit share: where two casters overlap in the kernel, s^2 is large and light bleeds
//        through; uBleed cuts the tail (p - b) / (1 - b) at the cost of darker penumbrae
//   ESM  (#define ESM) exp(c (t_occluder - t)) clamped to 1: over-darkens contacts less, but
//        brightens toward occluders near the receiver
#include "05_soft_shadows/soft_maps.glsl"

uniform sampler2D uMoments[MAX_LIGHTS];
uniform float uMinVariance;
uniform float uBleed;
uniform float uExponent;

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (uSoftLayer[i] < 0) return 1.0;
  SoftReceiver r = softReceiver(i, worldPos, N);
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r) || any(lessThan(r.uv, vec2(0.0))) || any(greaterThan(r.uv, vec2(1.0)))) return 1.0;
  vec2 range = uSoftDepthRange[i];
  float t = clamp((r.z - softBias(r) - range.x) / (range.y - range.x), 0.0, 1.0);
  vec4 m = texture(uMoments[i], r.uv);
#ifdef ESM
  float v = clamp(m.x * exp(-uExponent * t), 0.0, 1.0);
#else
  float variance = max(m.y - m.x * m.x, uMinVariance);
  float d = t - m.x;
  float v = t <= m.x ? 1.0 : clamp((variance / (variance + d * d) - uBleed) / (1.0 - uBleed), 0.0, 1.0);
#endif
  return v * softHorizon(i, worldPos, N);
}

#version 410 core
// Filterable shadow maps (lessons/05_soft_shadows/filterable_maps; lesson 05), blurred once per frame and
// read with one bilinear lookup, from the sphere's centre camera (soft_maps.glsl); the same bounds
// in C++: common/algorithms/moment_maps.
//   VSM   Chebyshev's one-sided bound p = s^2 / (s^2 + (t - mu)^2) for t > mu, an upper bound of
//         the lit share: where two casters overlap in the kernel, s^2 is large and light bleeds
//         through; uBleed cuts the tail (p - b) / (1 - b) at the cost of darker penumbrae
//   ESM   (#define ESM) exp(c (t_occluder - t)) clamped to 1: over-darkens contacts less, but
//         brightens toward occluders near the receiver
//   EVSM  (#define EVSM, EVSM_FOUR) the same bound on the warped depths: the smaller of the two
//   MSM   (#define MSM, MSM16) the Hamburger 4MSM bound from four moments, three Dirac deltas
#include "05_soft_shadows/soft_maps.glsl"

uniform sampler2D uMoments[MAX_LIGHTS];  // a cube's: its six faces in a 3 x 2 atlas

// GLSL ES 3.00 (WebGL2) indexes an array of samplers with constants only: a switch there.
vec4 momentsAt(int i, vec2 faceUv) {
  vec2 uv = uSoftFaces[i] == 6 ? (vec2(float(softFace % 3), float(softFace / 3)) + faceUv) / vec2(3.0, 2.0) : faceUv;
#ifdef SHADOWLAB_GLES
  switch (i) {
    case 0: return texture(uMoments[0], uv);
    case 1: return texture(uMoments[1], uv);
    case 2: return texture(uMoments[2], uv);
    default: return texture(uMoments[3], uv);
  }
#else
  return texture(uMoments[i], uv);
#endif
}
uniform float uMinVariance;
uniform float uBleed;
uniform float uExponent;
uniform vec2 uEvsm;          // c+, c-

float chebyshev(vec2 m, float t, float minVariance) {  // soft::chebyshevUpperBound
  if (t <= m.x) return 1.0;
  float variance = max(m.y - m.x * m.x, minVariance);
  float d = t - m.x;
  return variance / (variance + d * d);
}

float reduceBleeding(float v) { return clamp((v - uBleed) / (1.0 - uBleed), 0.0, 1.0); }  // soft::reduceBleeding

#ifdef MSM
#include "05_soft_shadows/msm.glsl"
#endif

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (uSoftLayer[i] < 0) return 1.0;
  SoftReceiver r = softReceiver(i, worldPos, N);
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r) || any(lessThan(r.uv, vec2(0.0))) || any(greaterThan(r.uv, vec2(1.0)))) return 1.0;
  vec2 range = uSoftDepthRange[i];
  float t = clamp((r.z - softBias(r) - range.x) / (range.y - range.x), 0.0, 1.0);
  vec4 m = momentsAt(i, r.uv);
#if defined(ESM)
  float v = clamp(m.x * exp(-uExponent * t), 0.0, 1.0);
#elif defined(EVSM)
  // soft::evsmLitShare: the variance floor scaled by each warp's slope.
  float w = 2.0 * t - 1.0;
  float p = exp(uEvsm.x * w), n = -exp(-uEvsm.y * w);
  float sp = 2.0 * uEvsm.x * p, sn = 2.0 * uEvsm.y * n;
  float v = chebyshev(m.xy, p, uMinVariance * sp * sp);
#ifdef EVSM_FOUR
  v = min(v, chebyshev(m.zw, n, uMinVariance * sn * sn));
#endif
  v = reduceBleeding(v);
#elif defined(MSM)
#ifdef MSM16
  m = kMsmDequantise * (m - vec4(0.035955884801, 0.0, 0.0, 0.0));
#endif
  float v = reduceBleeding(msmLitShare(m, t));
#else
  float v = reduceBleeding(chebyshev(m.xy, t, uMinVariance));
#endif
  return v * softHorizon(i, worldPos, N);
}

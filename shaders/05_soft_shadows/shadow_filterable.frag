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

uniform sampler2D uMoments[MAX_LIGHTS];
uniform float uMinVariance;
uniform float uBleed;
uniform float uExponent;
uniform vec2 uEvsm;          // c+, c-
uniform float uMomentBias;   // MSM's alpha

float chebyshev(vec2 m, float t, float minVariance) {  // soft::chebyshevUpperBound
  if (t <= m.x) return 1.0;
  float variance = max(m.y - m.x * m.x, minVariance);
  float d = t - m.x;
  return variance / (variance + d * d);
}

float reduceBleeding(float v) { return clamp((v - uBleed) / (1.0 - uBleed), 0.0, 1.0); }  // soft::reduceBleeding

#ifdef MSM
// soft::msmDequantise: the inverse of depth_moments.frag's quantisation.
const mat4 kMsmDequantise = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                                 0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                                 0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                                 0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);

// soft::msmLitShare: the Cholesky factorisation of the Hankel matrix of b, the two other support
// points, and the weight of the deltas in front of t.
float msmLitShare(vec4 m, float t) {
  vec4 b = mix(m, vec4(0.5), uMomentBias);
  float l32d22 = -b.x * b.y + b.z;
  float d22 = -b.x * b.x + b.y;
  float squaredVariance = -b.y * b.y + b.w;
  float d33d22 = squaredVariance * d22 - l32d22 * l32d22;
  float l32 = l32d22 / d22;
  vec3 c = vec3(1.0, t, t * t);
  c.y -= b.x;
  c.z -= b.y + l32 * c.y;
  c.y /= d22;
  c.z *= d22 / d33d22;
  c.y -= l32 * c.z;
  c.x -= c.y * b.x + c.z * b.y;
  float p = c.y / c.z, q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
  vec4 sw = z2 < t ? vec4(z1, t, 1.0, 1.0) : (z1 < t ? vec4(t, z1, 0.0, 1.0) : vec4(0.0));
  float quotient = (sw.x * z2 - b.x * (sw.x + z2) + b.y) / ((z2 - sw.y) * (t - z1));
  return 1.0 - clamp(sw.z + sw.w * quotient, 0.0, 1.0);
}
#endif

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (uSoftLayer[i] < 0) return 1.0;
  SoftReceiver r = softReceiver(i, worldPos, N);
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r) || any(lessThan(r.uv, vec2(0.0))) || any(greaterThan(r.uv, vec2(1.0)))) return 1.0;
  vec2 range = uSoftDepthRange[i];
  float t = clamp((r.z - softBias(r) - range.x) / (range.y - range.x), 0.0, 1.0);
  vec4 m = texture(uMoments[i], r.uv);
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

// Moment shadow maps' lookup (Peters and Klein 2015; lesson 05's technique=msm, included by
// shadow_filterable.frag): the 16-bit form read back, and the Hamburger 4MSM bound, the same as
// soft::msmDequantise and soft::msmLitShare (common/algorithms/moment_maps). Exercise 05.7 asks for
// the bound in C++: the student handout seals this file (tools/handout/sealed_shaders.txt).
uniform float uMomentBias;   // alpha

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

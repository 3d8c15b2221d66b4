#version 410 core
// The depth pass of a filterable shadow map (lessons/05_soft_shadows/filterable_maps; lesson 05): the same
// caster loop and alpha test as depth.frag, but it writes what can be blurred and then compared
// (common/algorithms/moment_maps has the same in C++):
//   VSM   (Donnelly and Lauritzen 2006) the first two moments (t, t^2) of the normalised depth t
//   ESM   (Annen et al. 2008) exp(c t)
//   EVSM  (Lauritzen and McCool 2008) the warps p = exp(c+ t'), n = -exp(-c- t') with t' = 2 t - 1,
//         and their squares: (p, p^2, n, n^2) (EVSM2 keeps the first two)
//   MSM   (Peters and Klein 2015) (t, t^2, t^3, t^4), or their optimised 16-bit quantisation
// t = (z - near) / (far - near), z the view distance of the fragment (gl_FragCoord.z linearised).
#include "common/caster_alpha.glsl"

uniform vec2 uDepthRange;  // near, far of the light camera
uniform float uExponent;   // ESM's c
uniform vec2 uEvsm;        // EVSM's c+, c-
uniform int uKind;         // 0 VSM, 1 ESM, 2 EVSM2, 3 EVSM4, 4 MSM: one program for all, the depth
                           // pass is not where the time goes
uniform bool uMsm16;       // MSM: store the quantised form (an RGBA16 target)

layout(location = 0) out vec4 fragMoments;

// Peters and Klein's optimised quantisation (soft::msmQuantise): the moments spread over [0, 1].
const mat4 kMsmQuantise = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                               32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                               -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                               39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);

void main() {
  casterAlphaTest();
  float n = uDepthRange.x, f = uDepthRange.y;
  float z = n * f / (f - gl_FragCoord.z * (f - n));
  float t = clamp((z - n) / (f - n), 0.0, 1.0);
  if (uKind == 1) {
    fragMoments = vec4(exp(uExponent * t), 0.0, 0.0, 1.0);
  } else if (uKind == 2 || uKind == 3) {
    float w = 2.0 * t - 1.0;
    float p = exp(uEvsm.x * w), m = -exp(-uEvsm.y * w);
    fragMoments = vec4(p, p * p, m, m * m);
  } else if (uKind == 4) {
    vec4 b = vec4(t, t * t, t * t * t, t * t * t * t);
    fragMoments = uMsm16 ? kMsmQuantise * b + vec4(0.035955884801, 0.0, 0.0, 0.0) : b;
  } else {
    fragMoments = vec4(t, t * t, 0.0, 1.0);
  }
}

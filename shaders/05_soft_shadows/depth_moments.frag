#version 410 core
// The depth pass of a filterable shadow map (lessons/05_soft_shadows/filterable_maps; lesson 05): the same
// caster loop and alpha test as depth.frag, but it writes what can be blurred and then compared:
//   VSM  (Donnelly and Lauritzen 2006) the first two moments (t, t^2) of the normalised depth t
//   ESM  (Annen et al. 2008, uEsm) exp(c t)
// t = (z - near) / (far - near), z the view distance of the fragment (gl_FragCoord.z linearised).
#include "common/caster_alpha.glsl"

uniform vec2 uDepthRange;  // near, far of the light camera
uniform float uExponent;   // ESM's c
uniform bool uEsm;         // one program for both: the depth pass is not where the time goes

out vec4 fragMoments;

void main() {
  casterAlphaTest();
  float n = uDepthRange.x, f = uDepthRange.y;
  float z = n * f / (f - gl_FragCoord.z * (f - n));
  float t = clamp((z - n) / (f - n), 0.0, 1.0);
  fragMoments = uEsm ? vec4(exp(uExponent * t), 0.0, 0.0, 1.0) : vec4(t, t * t, 0.0, 1.0);
}

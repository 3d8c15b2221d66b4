#version 410 core
// The depth pass of the techniques that warp space first (perspective shadow maps, LiSPSM;
// lessons/08_psm/projective_maps): depth.vert, plus the world-space texel-size bias of Kozlov et
// al., "Perspective Shadow Maps: Care and Feeding" §5 (fix 4), on every caster vertex:
//   P_biased = P + L min(a + b L_texel, maxOffset)
// L: the unit direction from the light; L_texel: the world size of one map texel at P, measured by
// moving P's map image one texel in x and y at the same depth and mapping it back. The paper folds
// that into one matrix K = M^-1 (C - I) M; K is rank one, d = K (P, 1) = u (r . (P, 1))
// (algorithms/psm/bias.hpp: texelStepFactors), and P' = (P + d.xyz) / (1 + d.w) since M is
// projective. Then M maps P_biased, never divided first.
layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec2 aUv;

uniform mat4 uLightViewProj;  // M: world -> map clip
uniform mat4 uModel;
uniform bool uWorldBias;
uniform vec4 uTexelStep;   // u = M^-1 (2/S, 2/S, 0, 0)
uniform vec4 uClipW;       // r: M's last row (clip w)
uniform vec4 uLightWorld;  // (position, 1), or (-direction, 0) for a directional light
uniform float uBiasA, uBiasB, uBiasMax;

out vec2 vUv;
#ifdef SHADOWLAB_NO_DEPTH_CLAMP
out vec2 vClipZW;  // the map's clip depth, clamped per fragment in depth_psm.frag
#endif

void main() {
  vUv = aUv;
  vec3 p = (uModel * vec4(aPosition, 1.0)).xyz;
  if (uWorldBias) {
    vec4 d = uTexelStep * dot(uClipW, vec4(p, 1.0));
    float w = 1.0 + d.w;
    // w <= 0: the one-texel step crossed the camera's plane at infinity: the texel is unbounded.
    float texel = w > 0.0 ? length((p + d.xyz) / w - p) : uBiasMax;
    vec3 L = uLightWorld.w == 0.0 ? -uLightWorld.xyz : p - uLightWorld.xyz / uLightWorld.w;
    float len = length(L);
    if (len > 0.0) p += L / len * min(uBiasA + uBiasB * texel, uBiasMax);
  }
  gl_Position = uLightViewProj * vec4(p, 1.0);
#ifdef SHADOWLAB_NO_DEPTH_CLAMP
  // No GL_DEPTH_CLAMP (WebGL2 without EXT_depth_clamp): depth_psm.frag clamps the depth per
  // fragment; z = 0 keeps what lies before the near plane (or beyond the far one) from being clipped.
  vClipZW = gl_Position.zw;
  gl_Position.z = 0.0;
#endif
}

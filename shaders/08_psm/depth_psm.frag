#version 410 core
// The depth pass of the techniques that warp space first, fragment: depth.frag's alpha test and,
// where the context has no GL_DEPTH_CLAMP (WebGL2 without EXT_depth_clamp), the clamp itself:
// depth_psm.vert hands the map's clip (z, w) over and keeps every fragment inside the near and far
// planes; here the depth is clamped to [0, 1] as GL_DEPTH_CLAMP would, after glPolygonOffset's
// slope term (gl_FragDepth replaces the offset depth the rasteriser made).
#include "common/caster_alpha.glsl"
#ifdef SHADOWLAB_NO_DEPTH_CLAMP
in vec2 vClipZW;
uniform float uSlopeOffset;  // glPolygonOffset's factor: times the depth's largest screen slope
#endif

void main() {
#ifdef SHADOWLAB_NO_DEPTH_CLAMP
  float depth = 0.5 * vClipZW.x / vClipZW.y + 0.5;  // before a discard: derivatives need the whole quad
  float slope = max(abs(dFdx(depth)), abs(dFdy(depth)));
#endif
  casterAlphaTest();
#ifdef SHADOWLAB_NO_DEPTH_CLAMP
  gl_FragDepth = clamp(depth + uSlopeOffset * slope, 0.0, 1.0);
#endif
}

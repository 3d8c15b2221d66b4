#version 410 core
// Debug lines as screen-space quads uWidth pixels wide (common/line_quad.glsl: the near-plane clip
// and the quad's corners, shared with lines_quad.vert where there is no geometry shader).
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
in vec4 vColor[];
out vec4 gColor;
#include "common/line_quad.glsl"

#ifdef CLIP_DISTANCE0
// The post-projective view's lines (post_lines.vert) are clipped at their own w = 0 by
// gl_ClipDistance[0]: clip the segment here first, as the rasteriser would have.
#endif

void main() {
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
#ifdef CLIP_DISTANCE0
  float ca = gl_in[0].gl_ClipDistance[0], cb = gl_in[1].gl_ClipDistance[0];
  if (ca < 0.0 && cb < 0.0) return;
  if (ca < 0.0) a = mix(a, b, ca / (ca - cb));
  if (cb < 0.0) b = mix(b, a, cb / (cb - ca));
#endif
  if (!clipToNear(a, b)) return;
  for (int i = 0; i < 4; ++i) {
    gl_Position = lineQuadCorner(a, b, i, uViewport, uWidth);
    gColor = vColor[i < 2 ? 0 : 1];
#ifdef CLIP_DISTANCE0
    gl_ClipDistance[0] = 1.0;  // already clipped above
#endif
    EmitVertex();
  }
  EndPrimitive();
}

#version 410 core
// Debug lines as screen-space quads uWidth pixels wide: core profile OpenGL draws GL_LINES one
// pixel wide (wider lines are deprecated and often unsupported), too thin on a projector. Each
// segment is first clipped to the near plane (z >= -w) so that a line passing behind the camera
// does not flip across the screen; the quad is extended by half a width at both ends so that
// corners of boxes and frusta close.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
in vec4 vColor[];
out vec4 gColor;

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
  float da = a.z + a.w, db = b.z + b.w;  // signed distance to the near plane, in clip units
  if (da < 0.0 && db < 0.0) return;
  if (da < 0.0) a = mix(a, b, da / (da - db));
  if (db < 0.0) b = mix(b, a, db / (db - da));
  vec2 halfViewport = 0.5 * uViewport;
  vec2 sa = a.xy / a.w * halfViewport, sb = b.xy / b.w * halfViewport;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 h = 0.5 * uWidth / halfViewport;  // half a width, in NDC units per axis
  // Counter-clockwise on screen whichever way the segment runs: face culling keeps it.
  vec2 offsets[4] = vec2[4](-along + across, -along - across, along + across, along - across);
  for (int i = 0; i < 4; ++i) {
    vec4 p = i < 2 ? a : b;
    gl_Position = vec4(p.xy + offsets[i] * h * p.w, p.zw);
    gColor = vColor[i < 2 ? 0 : 1];
#ifdef CLIP_DISTANCE0
    gl_ClipDistance[0] = 1.0;  // already clipped above
#endif
    EmitVertex();
  }
  EndPrimitive();
}

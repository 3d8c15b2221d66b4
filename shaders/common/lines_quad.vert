#version 410 core
// Debug lines as screen-space quads without a geometry shader (WebGL2 has none): the CPU gives each
// of a segment's six vertices (two triangles) both ends and its corner, and this does for one corner
// what lines.geom does for four (common/line_quad.glsl).
layout(location = 0) in vec4 aStart;  // w = 1 unless given: the post-projective view's ends are homogeneous
layout(location = 1) in vec4 aEnd;
layout(location = 2) in vec4 aColor;
layout(location = 3) in float aCorner;  // 0, 1 at the start; 2, 3 at the end
uniform mat4 uViewProj;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
out vec4 gColor;
#include "common/line_quad.glsl"
#ifdef CLIP_DISTANCE0
// The post-projective view's lines (as post_lines.vert and lines.geom draw them): drawn once as
// given and once negated (uSign), each clipped at its own w = 0 before the display projection.
uniform float uSign;
#endif
void main() {
  vec4 a = aStart, b = aEnd;
  gColor = aColor;
  bool drawn = true;
#ifdef CLIP_DISTANCE0
  a *= uSign, b *= uSign;
  if (a.w < 0.0 && b.w < 0.0) drawn = false;
  if (a.w < 0.0) a = mix(a, b, a.w / (a.w - b.w));
  if (b.w < 0.0) b = mix(b, a, b.w / (b.w - a.w));
#endif
  a = uViewProj * a, b = uViewProj * b;
  if (!drawn || !clipToNear(a, b)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind the camera: outside the clip volume
    return;
  }
  gl_Position = lineQuadCorner(a, b, int(aCorner), uViewport, uWidth);
}

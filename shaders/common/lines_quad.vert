#version 410 core
// Debug lines as screen-space quads without a geometry shader (WebGL2 has none): the CPU gives each
// of a segment's six vertices (two triangles) both ends and its corner, and this does for one corner
// what lines.geom does for four (common/line_quad.glsl).
layout(location = 0) in vec3 aStart;
layout(location = 1) in vec3 aEnd;
layout(location = 2) in vec4 aColor;
layout(location = 3) in float aCorner;  // 0, 1 at the start; 2, 3 at the end
uniform mat4 uViewProj;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
out vec4 gColor;
#include "common/line_quad.glsl"
void main() {
  vec4 a = uViewProj * vec4(aStart, 1.0), b = uViewProj * vec4(aEnd, 1.0);
  gColor = aColor;
  if (!clipToNear(a, b)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind the camera: outside the clip volume
    return;
  }
  gl_Position = lineQuadCorner(a, b, int(aCorner), uViewport, uWidth);
}

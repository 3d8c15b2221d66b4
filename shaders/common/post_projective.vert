#version 410 core
// The scene after the camera's projection (common/technique/post_projective_view): the world point
// becomes h = P V x, homogeneous, and the display camera takes h as it is (uSign = -1 and the clip
// plane at w = 0 draw the part behind the camera, which lies beyond the plane at infinity).
layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uCamera;   // the camera whose post-projective space this is (P V)
uniform mat4 uDisplayView;  // the display camera, looking at the unit cube from outside
uniform mat4 uDisplay;      // its projection times uDisplayView
uniform float uSign;        // +1: in front of the camera (w > 0); -1: behind it
uniform vec2 uBox;          // what is drawn: |x|, |y| <= uBox.x and -uBox.x <= z <= uBox.y (times w)

out vec4 vView;  // display view space, homogeneous: divided per fragment, for flat shading
out vec2 vDepth;  // post-projective (z, w): the colour ramp from the near face to the far one

void main() {
  vec4 h = uSign * (uCamera * (uModel * vec4(aPosition, 1.0)));
  // In front of the camera plane (or, negated, behind it), and inside a box around the unit cube:
  // what lies beside the frustum near the camera plane would stretch to infinity and hide it.
  gl_ClipDistance[0] = h.w;
  gl_ClipDistance[1] = uBox.x * h.w - h.x;
  gl_ClipDistance[2] = uBox.x * h.w + h.x;
  gl_ClipDistance[3] = uBox.x * h.w - h.y;
  gl_ClipDistance[4] = uBox.x * h.w + h.y;
  gl_ClipDistance[5] = uBox.x * h.w + h.z;
  gl_ClipDistance[6] = uBox.y * h.w - h.z;
  gl_Position = uDisplay * h;
  vView = uDisplayView * h;
  vDepth = h.zw;
}

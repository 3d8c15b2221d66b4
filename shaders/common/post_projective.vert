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
#ifdef SHADOWLAB_NO_CLIP_DISTANCE
// No gl_ClipDistance (WebGL2): the same seven distances interpolated, and post_projective.frag
// discards where one is negative. Each is linear in clip space, so the pixels kept are the ones the
// clipper would have kept.
out float vClip[7];
#else
out float gl_ClipDistance[7];  // sized: the loop below indexes it
#endif

void main() {
  vec4 h = uSign * (uCamera * (uModel * vec4(aPosition, 1.0)));
  // In front of the camera plane (or, negated, behind it), and inside a box around the unit cube:
  // what lies beside the frustum near the camera plane would stretch to infinity and hide it.
  float clip[7] = float[7](h.w, uBox.x * h.w - h.x, uBox.x * h.w + h.x, uBox.x * h.w - h.y, uBox.x * h.w + h.y,
                           uBox.x * h.w + h.z, uBox.y * h.w - h.z);
  for (int k = 0; k < 7; ++k) {
#ifdef SHADOWLAB_NO_CLIP_DISTANCE
    vClip[k] = clip[k];
#else
    gl_ClipDistance[k] = clip[k];
#endif
  }
  gl_Position = uDisplay * h;
  vView = uDisplayView * h;
  vDepth = h.zw;
}

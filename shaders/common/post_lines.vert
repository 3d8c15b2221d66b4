#version 410 core
// Lines between homogeneous post-projective points (algorithms/psm/post_shapes): drawn once as
// given and once negated, each clipped at w = 0, so a segment through infinity is drawn as one.
layout(location = 0) in vec4 aPosition;
layout(location = 1) in vec4 aColor;
uniform mat4 uDisplay;
uniform float uSign;
out vec4 vColor;
void main() {
  vec4 p = uSign * aPosition;
  gl_ClipDistance[0] = p.w;
  gl_Position = uDisplay * p;
  vColor = aColor;
}

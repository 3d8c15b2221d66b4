#version 410 core
// The records of one level, scattered (common/algorithms/hybrid_map: buildHybrid): one point per
// level-k texel (gl_VertexID); a texel that merged is sent outside the clip volume, one that was
// kept lands on the texel of its record in the record texture with its four children's words.
// GL 4.1 has no scattered writes from a fragment shader; a point per texel is the scatter.
uniform sampler2D uValues;        // level k's merge grid
uniform usampler2D uStarts;       // level k's record starts
uniform sampler2D uChildValues;   // level k-1: the depth map (k = 1) or its merge grid
uniform usampler2D uChildStarts;  // level k-1's record starts (k >= 2)
uniform int uLevel, uSize, uChildSize;
uniform int uRowWidth, uRows;     // records a row, rows of the record texture

flat out uvec4 vRecord;

uint childWord(ivec2 c) {
  if (c.x >= uChildSize || c.y >= uChildSize) return floatBitsToUint(1.0);  // outside: the far plane
  float v = texelFetch(uChildValues, c, 0).r;
  if (uLevel == 1 || v >= 0.0) return floatBitsToUint(v);
  return 0x80000000u | texelFetch(uChildStarts, c, 0).r;
}

void main() {
  ivec2 t = ivec2(gl_VertexID % uSize, gl_VertexID / uSize);
  vRecord = uvec4(0u);
  if (texelFetch(uValues, t, 0).r >= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // merged: no record
    return;
  }
  ivec2 c = 2 * t;
  vRecord = uvec4(childWord(c), childWord(c + ivec2(1, 0)), childWord(c + ivec2(0, 1)), childWord(c + ivec2(1, 1)));
  int r = int(texelFetch(uStarts, t, 0).r);
  vec2 texel = vec2(r % uRowWidth, r / uRowWidth) + 0.5;
  gl_Position = vec4(texel / vec2(uRowWidth, uRows) * 2.0 - 1.0, 0.0, 1.0);
}

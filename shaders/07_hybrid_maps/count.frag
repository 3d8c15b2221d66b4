#version 410 core
// The count pyramid above the root level (common/algorithms/hybrid_map: indexPyramid, up): records
// per subtree, the sum of the four children's, up to a single texel holding the total.
uniform usampler2D uChildCounts;
uniform int uChildSize;

layout(location = 0) out uvec4 outCount;

uvec4 childCount(ivec2 c) {
  if (c.x >= uChildSize || c.y >= uChildSize) return uvec4(0u);
  return texelFetch(uChildCounts, c, 0);
}

void main() {
  ivec2 c = 2 * ivec2(gl_FragCoord.xy);
  outCount = childCount(c) + childCount(c + ivec2(1, 0)) + childCount(c + ivec2(0, 1)) + childCount(c + ivec2(1, 1));
}

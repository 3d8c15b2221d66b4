#version 410 core
// The record starts, top down (common/algorithms/hybrid_map: indexPyramid, down): a texel's first
// record comes after its parent's start, the parent's own record (when it has one) and the
// subtrees of its earlier siblings, (x, y), (x+1, y), (x, y+1) before (x+1, y+1).
uniform usampler2D uParentStarts;  // level k+1
uniform sampler2D uParentValues;   // level k+1's merge grid (when it has records: uParentOwns)
uniform bool uParentOwns;          // k + 1 <= levels
uniform usampler2D uCounts;        // level k
uniform int uSize;                 // level k texels a side

out uint outStart;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  ivec2 parent = t >> 1;
  uint s = texelFetch(uParentStarts, parent, 0).r;
  if (uParentOwns && !(texelFetch(uParentValues, parent, 0).r >= 0.0)) s += 1u;
  int sibling = (t.x & 1) + 2 * (t.y & 1);
  ivec2 base = t & ~1;
  for (int j = 0; j < 3; ++j) {
    ivec2 q = base + ivec2(j & 1, j >> 1);
    if (j < sibling && q.x < uSize && q.y < uSize) s += texelFetch(uCounts, q, 0).r;
  }
  outStart = s;
}

#version 410 core
// The root grid (common/algorithms/hybrid_map: buildHybrid): per level-L texel a leaf (the depth's
// float bits) or a pointer to its record. Levels 0: the depth map itself, word for word.
uniform sampler2D uValues;   // level L's merge grid, or the depth map when L = 0
uniform usampler2D uStarts;  // level L's record starts (L >= 1)
uniform bool uHasRecords;    // L >= 1

out uint outWord;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  float v = texelFetch(uValues, t, 0).r;
  outWord = !uHasRecords || v >= 0.0 ? floatBitsToUint(v) : (0x80000000u | texelFetch(uStarts, t, 0).r);
}

// The hybrid map's lookup, shared by its visibility (shadow_hybrid.frag) and its views: from the
// root word over a source texel down the index to the finest stored depth. Mirrors
// common/algorithms/hybrid_map (descend); keep the two in step.
//   root     R32UI, ceil(N / 2^levels) texels a side: a leaf's float bits, or HYBRID_POINTER | record
//   records  RGBA32UI, HYBRID_RECORD_ROW records a row: the four children's words of a texel that
//            did not merge, child i at (x + (i & 1), y + (i >> 1)) one level down
const uint HYBRID_POINTER = 0x80000000u;
const int HYBRID_RECORD_ROW_BITS = 10;  // 1024 records a row (tech::HybridBuilder::kRecordRow)

struct HybridTexel {
  float depth;  // the stored window depth
  int level;    // where it was stored: 0 full resolution, `levels` the root grid
  int steps;    // pointers followed
};

// Source texel s (inside the map: 0 <= s < size) of a map of `levels` levels.
HybridTexel hybridDescend(usampler2D root, usampler2D records, int levels, ivec2 s) {
  HybridTexel t;
  t.level = levels;
  t.steps = 0;
  uint word = texelFetch(root, s >> levels, 0).r;
  for (int k = 0; k < 3; ++k) {  // at most hybrid::kMaxLevels pointers
    if ((word & HYBRID_POINTER) == 0u || t.level == 0) break;
    uint r = word & ~HYBRID_POINTER;
    t.level -= 1;
    uvec4 record = texelFetch(records, ivec2(int(r & ((1u << HYBRID_RECORD_ROW_BITS) - 1u)),
                                             int(r >> HYBRID_RECORD_ROW_BITS)), 0);
    word = record[((s.x >> t.level) & 1) | (((s.y >> t.level) & 1) << 1)];
    t.steps += 1;
  }
  t.depth = uintBitsToFloat(word);
  return t;
}

// The hybrid map's stored form, as its lookup (07_hybrid_maps/hybrid_descent.glsl, exercise 07.5) reads it:
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

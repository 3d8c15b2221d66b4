// Lesson 07, GLSL exercise: the reference (sealed in the student handout; exercises.glsl says what
// the function does). common/hybrid_descent.glsl includes this file unless SHADOWLAB_STUDENT_DESCENT
// is set.

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

// Lesson 07, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). 07_hybrid_maps/hybrid_descent.glsl includes this file unless SHADOWLAB_STUDENT_DESCENT
// is set.

// Source texel s (inside the map: 0 <= s < size) of a map of `levels` levels.
HybridTexel hybridDescend(usampler2D root, usampler2D records, int levels, ivec2 s) {
  HybridTexel t;
  t.level = levels;
  t.steps = 0;
  uint word = texelFetch(root, s >> levels, 0).r;
  // One pointer a level, so at most `levels` (hybrid::kMaxLevels = 3). The count from the uniform,
  // not the constant 3: the compiler cannot unroll the loop then, and llvmpipe leaves it as soon as
  // every pixel of a group has found its leaf (lesson 07's pcf preset 133-137 -> 108-117 ms).
  for (int k = 0; k < levels; ++k) {
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

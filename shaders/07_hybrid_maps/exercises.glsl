// Lesson 07, GLSL exercise: YOUR descent through the hybrid map's index, written in the shader.
// With impl=student, the hybrid technique's visibility (shaders/07_hybrid_maps/shadow_hybrid.frag) looks up
// every shadow-map tap of every pixel with this function:
//   lesson_07_hybrid_maps --set impl=student
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=07 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns depth 1.0
// (the far plane) at the root: every pixel is lit, no shadows. Delete its SHADOWLAB_STUB line when
// you write it.
//
// Provided (shaders/07_hybrid_maps/hybrid_texel.glsl), for you to use:
//   root     R32UI, one texel per 2^levels x 2^levels source texels: a leaf (a stored depth's float
//            bits) or a pointer, HYBRID_POINTER | r, to record r
//   records  RGBA32UI, record r at texel (r & 1023, r >> HYBRID_RECORD_ROW_BITS) (1024 a row): the
//            four words of the children of a texel that did not merge, child i = (x & 1) + 2 (y & 1)
//            of the level below, each again a leaf or a pointer
//   struct HybridTexel { float depth; int level; int steps; }
// and texelFetch(usampler, ivec2, 0) (an uvec4; .r for the root), uintBitsToFloat(uint).

// EXERCISE 07.5 (GLSL): the index descent ([LiHua2016] Algorithm 2; exercise 07.3 is the same in
// C++). For source texel s of a map of `levels` levels: read the root word at s >> levels; while
// it is a pointer (word & HYBRID_POINTER) and the level is above 0, go one level down (level - 1)
// into its record r = word & ~HYBRID_POINTER, and take the word of the child under s there:
// ((s.x >> level) & 1) | (((s.y >> level) & 1) << 1) at the new level. A map has at most 3 levels.
// Return the leaf: its depth (the word's bits as a float), the level it was stored at (levels when
// the root word is a leaf, 0 at full resolution) and the pointers followed.
HybridTexel hybridDescend(usampler2D root, usampler2D records, int levels, ivec2 s) {
  // SHADOWLAB_STUB 07.5: delete this line when you write the exercise
  return HybridTexel(1.0, levels, 0);
}

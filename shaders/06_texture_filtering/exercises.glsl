// Lesson 06, GLSL exercises: YOUR RIP-map sampler, written in the shader. With impl=student and
// sampling=rip_map, scene.frag filters every pixel with these functions:
//   lesson_06_texture_filtering --set impl=student --preset rip_vs_mip
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=06 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). Each stub compiles and returns a
// neutral value; delete its SHADOWLAB_STUB line when you write it.
//
// Provided by the lesson (scene.frag), for you to call:
//   ivec2 ripLevelSize(ivec2 level)     the size of RIP level (lu, lv): (w >> lu, h >> lv), at least 1
//   vec4 ripTexel(ivec2 level, ivec2 t)  texel t of that level, t wrapped (REPEAT), any integer t

// EXERCISE 06.8 (GLSL): a RIP map keeps levels shrunk along u and along v independently
// ([Tarantsev-L12], RIP maps), so each axis gets its own level of detail. The footprint's extent
// along u in texels is max(|dUVdx.x|, |dUVdy.x|) * texSize.x, along v the same with .y and
// texSize.y; each lambda is log2 of its extent (of max(extent, 1e-8), so log2 never sees 0).
// Return vec2(lambda_u, lambda_v); the lesson adds the LOD bias and clamps to the levels it has.
vec2 ripLevelOfDetail(vec2 dUVdx, vec2 dUVdy, ivec2 texSize) {
  // SHADOWLAB_STUB 06.8: delete this line when you write the exercise
  return vec2(0.0);
}

// EXERCISE 06.9 (GLSL): bilinear filtering inside one RIP level, by hand (the levels live side by
// side in one atlas texture, so the hardware filter would bleed between them). With
// size = ripLevelSize(level): p = fract(uv) * size - 0.5, i0 = floor(p), f = p - i0; blend the
// texels i0, i0 + (1,0), i0 + (0,1), i0 + (1,1) with the weights (1-f.x)(1-f.y), f.x(1-f.y),
// (1-f.x)f.y, f.x f.y (exercise 06.4 in C++ is the same filter).
vec4 ripBilinear(ivec2 level, vec2 uv) {
  // SHADOWLAB_STUB 06.9: delete this line when you write the exercise
  return vec4(0.0);
}

// Lesson 02, GLSL exercises: YOUR shadow-map lookup, written in the shader. With impl=student and
// compare=manual, scene.frag calls these functions for every pixel:
//   lesson_02_shadow_maps --set impl=student --set compare=manual
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=02 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). Each stub compiles and returns a
// neutral value; delete its SHADOWLAB_STUB line when you write it.

// EXERCISE 02.4 (GLSL): the depth comparison ARB_shadow does with GL_LEQUAL, and a bias: return
// 1.0 (lit) when fragmentDepth - bias <= storedDepth, else 0.0 (shadowed). [Boreskov2005]
float shadowCompare(float fragmentDepth, float storedDepth, float bias) {
  // SHADOWLAB_STUB 02.4: delete this line when you write the exercise
  return 1.0;
}

// EXERCISE 02.5 (GLSL): the whole lookup. shadowCoord = T * (p, 1), T the shadow texture matrix
// (exercise 02.1): homogeneous, so divide by w first to get (u, v, depth). Where the light saw
// nothing return 1.0 (lit): behind the light (w <= 0), outside the map (u or v outside [0, 1]) or
// beyond its far plane (depth > 1). Otherwise read the stored depth, texture(depthMap, uv).r, and
// compare with your shadowCompare.
float shadowLookup(sampler2D depthMap, vec4 shadowCoord, float bias) {
  // SHADOWLAB_STUB 02.5: delete this line when you write the exercise
  return 1.0;
}

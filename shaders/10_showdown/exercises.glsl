// Lesson 10, GLSL exercise: YOUR choice of the cascade, written in the shader. With impl=student the
// cascaded shadow maps (technique=csm, shaders/10_showdown/shadow_cascades.frag) pick every pixel's
// cascade, and the blend band's mix, with this function:
//   lesson_10_showdown --set impl=student --set csm.colours=on
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=10 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns a neutral
// value; delete its SHADOWLAB_STUB line when you write it.

// EXERCISE 10.4 (GLSL): exercise 10.3 (cascadeAt) in the shader ([Zhang2006]).
// The shader declares, for each light (`light` < PSM_LIGHTS):
//   int uPsmLayers[light]     how many cascades the light has (0: none)
//   float uCsmNear            where cascade 0 starts (view depth, every light)
//   vec4 uCsmFar[light]       where cascades 0..3 end: uCsmFar[light][k], increasing
//   float uCsmBand            the blend band, a fraction of a cascade's depth range (0: none)
// Return the cascade k whose range [start, uCsmFar[light][k]] holds `depth` (cascade k starts where
// k - 1 ends; a depth exactly on a split belongs to the nearer cascade), or -1 when the light has no
// cascade, or depth lies before uCsmNear or beyond the last cascade's end. nextWeight: how much of
// cascade k + 1 is mixed in; 0 unless k is not the last cascade, uCsmBand > 0 and depth lies in the
// band at the far end of k, the last uCsmBand * (its depth range) before its end, where the weight
// grows linearly from 0 at the band's start to 1 at the split. Always set nextWeight (0 for -1).
int cascadeAt(int light, float depth, out float nextWeight) {
  // SHADOWLAB_STUB 10.4: delete this line when you write the exercise
  nextWeight = 0.0;
  return -1;
}

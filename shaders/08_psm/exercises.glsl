// Lesson 08, GLSL exercise: YOUR lookup of a point in a perspective shadow map, written in the
// shader. With impl=student the PSM technique (shaders/08_psm/projective_maps.glsl, read by
// shadow_psm.frag) finds every pixel's place in its map with this function:
//   lesson_08_psm --set impl=student --preset behind
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=08 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns a neutral
// value; delete its SHADOWLAB_STUB line when you write it.

// EXERCISE 08.3 (GLSL): the point's place in the map ([Kozlov2004] §2-3). worldToClip is the map's
// whole projective step, world -> the camera's post-projective space -> the light camera's clip
// space: apply it to the homogeneous point h = worldToClip * (worldPos, 1), never divide part way.
// Only the sign of h.w says whether the map knows the point: for h.w > 0 return
// vec4(the map's window coordinates (u, v, depth) = h.xyz / h.w * 0.5 + 0.5, 1.0); for h.w <= 0
// (or not a number) the point is outside every light frustum, whatever side of the eye it lies on
// (with the inverse projection of lesson 09 w flips sign): return vec4(0.0), and the lesson calls
// it lit. Depths beyond the map's far plane (depth > 1) are returned as they are: the caller
// decides.
vec4 psmMapCoords(mat4 worldToClip, vec3 worldPos) {
  // SHADOWLAB_STUB 08.3: delete this line when you write the exercise
  return vec4(0.0);
}

// Lesson 05, GLSL exercise: YOUR PCSS blocker search, written in the shader. With impl=student and
// technique=pcss (the default), the PCSS technique (shaders/05_soft_shadows/shadow_pcss.frag) searches for
// the blockers of every pixel with this function:
//   lesson_05_soft_shadows --set impl=student --preset contact_hardening
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=05 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns a neutral
// value; delete its SHADOWLAB_STUB line when you write it.
//
// Provided by the technique (shadow_pcss.frag, soft_maps.glsl), for you to call:
//   float softDepthAt(int light, int k, vec2 uv)  what light `light`'s map k stores at uv, as a
//                                                 distance along the light's axis (k = 0: the map
//                                                 from the sphere's centre, the one PCSS uses)
//   SEARCH_TAPS, uSearchTaps[k]                   the search's Poisson taps in the unit disk

// EXERCISE 05.6 (GLSL): the blocker search of PCSS ([Fernando2005]): over the SEARCH_TAPS taps
// o = turn * uSearchTaps[k] * radius around uv, the stored distance zb = softDepthAt(light, 0,
// uv + o) is a blocker when it is nearer the light than the receiver's plane there:
// zb < z + dot(plane, o) - bias. Return vec2(the blockers' mean distance, how many there are), or
// vec2(0.0) when there is none (the lesson then skips the filter: nothing hides the light).
vec2 blockerSearch(int light, vec2 uv, float z, vec2 plane, float bias, float radius, mat2 turn) {
  // SHADOWLAB_STUB 05.6: delete this line when you write the exercise
  return vec2(0.0);
}

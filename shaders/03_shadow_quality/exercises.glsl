// Lesson 03, GLSL exercise: YOUR percentage-closer filter, written in the shader. With impl=student
// and filter=pcf_nxn, the uniform shadow-map technique (shaders/03_shadow_quality/shadow_uniform.frag) filters
// every 2D map lookup with this function:
//   lesson_03_shadow_quality --set impl=student --set filter=pcf_nxn --set pcf.size=5
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=03 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns a neutral
// value; delete its SHADOWLAB_STUB line when you write it.
//
// Provided by the technique (shadow_uniform.frag), for you to call:
//   float tap2D(int map, vec3 p)   one comparison in light `map`'s 2D map: 1.0 (lit) when the depth
//                                  p.z <= the depth stored at the texel under p.xy, else 0.0
//                                  (the hardware's GL_LEQUAL comparison, nearest texel)

// EXERCISE 03.6 (GLSL): the N x N PCF kernel ([Boreskov2005], [Tarantsev-L12]): the mean of the
// n * n comparisons at the texel offsets o = (x, y) * texel, x and y from -n/2 to n/2 (n is odd;
// texel = 1 / map size). Each tap compares the receiver plane's depth at the tap,
// depth + dot(dzduv, o) (dzduv is the receiver's depth slope per unit of uv, 0 when
// bias.receiver_plane is off), so a sloped receiver does not shadow itself under the wide kernel.
float pcfKernel(int map, vec2 uv, float depth, vec2 dzduv, float texel, int n) {
  // SHADOWLAB_STUB 03.6: delete this line when you write the exercise
  return 1.0;
}

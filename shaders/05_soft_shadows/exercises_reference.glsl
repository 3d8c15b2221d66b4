// Lesson 05, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). shadow_pcss.frag includes this file unless SHADOWLAB_STUDENT_PCSS is set.

vec2 blockerSearch(int light, vec2 uv, float z, vec2 plane, float bias, float radius, mat2 turn) {
  float sum = 0.0;
  int blockers = 0;
  for (int k = 0; k < SEARCH_TAPS; ++k) {
    vec2 o = turn * uSearchTaps[k] * radius;
    float zb = softDepthAt(light, 0, uv + o);
    if (zb < z + dot(plane, o) - bias) {
      sum += zb;
      ++blockers;
    }
  }
  return blockers == 0 ? vec2(0.0) : vec2(sum / float(blockers), float(blockers));
}

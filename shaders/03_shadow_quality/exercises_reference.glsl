// Lesson 03, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). shadow_uniform.frag includes this file unless SHADOWLAB_STUDENT_PCF is set.

float pcfKernel(int map, vec2 uv, float depth, vec2 dzduv, float texel, int n) {
  int h = n / 2;
  float sum = 0.0;
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x) {
      vec2 o = vec2(x, y) * texel;
      sum += tap2D(map, vec3(uv + o, depth + dot(dzduv, o)));
    }
  return sum / float(n * n);
}

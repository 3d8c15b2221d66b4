// Lesson 09, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). shadow_psm.frag includes this file unless SHADOWLAB_STUDENT_PSM_FACES is set.

int cubeFaceLayer(vec3 q, vec4 light, int layerOfFace[6]) {  // algorithms/psm/cube_faces.cpp, cubeFaceOf
  vec3 v = light.w == 0.0 ? -light.xyz : q - light.xyz;
  vec3 o = light.w == 0.0 ? q : light.xyz;
  float best = 3.0e38;
  int layer = -1;
  for (int f = 0; f < 6; ++f) {
    int k = layerOfFace[f];
    vec3 n = vec3(0.0);
    n[f / 2] = (f % 2 == 0) ? 1.0 : -1.0;
    float nv = dot(n, v);
    if (k < 0 || nv <= 0.0) continue;
    float t = (1.0 - dot(n, o)) / nv;
    if (t < best) {
      best = t;
      layer = k;
    }
  }
  return layer;
}

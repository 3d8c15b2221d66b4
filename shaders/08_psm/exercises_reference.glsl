// Lesson 08, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). projective_maps.glsl includes this file unless SHADOWLAB_STUDENT_PSM_LOOKUP
// is set.

vec4 psmMapCoords(mat4 worldToClip, vec3 worldPos) {
  vec4 h = worldToClip * vec4(worldPos, 1.0);
  if (!(h.w > 0.0)) return vec4(0.0);  // outside every light frustum: nothing known
  return vec4(h.xyz / h.w * 0.5 + 0.5, 1.0);
}

// Lesson 04, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). volume.geom includes this file unless SHADOWLAB_STUDENT_GLSL is set. The body
// is the expression volume.geom's atInfinity held, on a line of its own so that the handout check
// (tools/handout/check_handout.sh) finds it wherever it ships.

vec4 extrudeToInfinity(vec3 p, vec4 light) {
  return vec4(p * light.w - light.xyz, 0.0);
}

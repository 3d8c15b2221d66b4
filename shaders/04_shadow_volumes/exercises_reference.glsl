// Lesson 04, GLSL exercise: the reference (sealed in the student handout; exercises.glsl says what
// the function does). volume.geom includes this file unless SHADOWLAB_STUDENT_GLSL is set.

vec4 extrudeToInfinity(vec3 p, vec4 light) { return vec4(p * light.w - light.xyz, 0.0); }

// Lesson 02, GLSL exercises: the reference (withheld from the student handout; exercises.glsl says
// what each function does). scene.frag includes this file unless SHADOWLAB_STUDENT_GLSL is set.

float shadowCompare(float fragmentDepth, float storedDepth, float bias) {
  return fragmentDepth - bias <= storedDepth ? 1.0 : 0.0;  // the comparison ARB_shadow does in hardware
}

float shadowLookup(sampler2D depthMap, vec4 shadowCoord, float bias) {
  if (shadowCoord.w <= 0.0) return 1.0;  // behind the light: the spot cone is zero there
  vec3 p = shadowCoord.xyz / shadowCoord.w;
  if (p.z > 1.0) return 1.0;  // beyond the light's far plane: nothing known
  if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
  return shadowCompare(p.z, texture(depthMap, p.xy).r, bias);
}

// Lesson 06, GLSL exercises: the reference (withheld from the student handout; exercises.glsl says
// what each function does). scene.frag includes this file unless SHADOWLAB_STUDENT_GLSL is set.

vec2 ripLevelOfDetail(vec2 dUVdx, vec2 dUVdy, ivec2 texSize) {
  vec2 extent = max(abs(dUVdx), abs(dUVdy)) * vec2(texSize);  // texels along u and along v
  return log2(max(extent, vec2(1e-8)));
}

vec4 ripBilinear(ivec2 level, vec2 uv) {
  ivec2 size = ripLevelSize(level);
  vec2 p = fract(uv) * vec2(size) - 0.5;
  ivec2 i0 = ivec2(floor(p));
  vec2 f = p - vec2(i0);
  return mix(mix(ripTexel(level, i0), ripTexel(level, i0 + ivec2(1, 0)), f.x),
             mix(ripTexel(level, i0 + ivec2(0, 1)), ripTexel(level, i0 + ivec2(1, 1)), f.x), f.y);
}

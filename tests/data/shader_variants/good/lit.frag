#version 410 core
// shader_check --variants fixture (tests/shaders.cmake): valid in every variant good.log records;
// gap.log leaves SOFT out, which the coverage check must name with include/shadow.glsl's line.
#include "include/shadow.glsl"

out vec4 fragColor;
void main() {
#ifdef TINT
  fragColor = vec4(vec3(shadow()) * TINT, 1.0);
#else
  fragColor = vec4(vec3(shadow()), 1.0);
#endif
}

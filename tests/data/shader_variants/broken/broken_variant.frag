#version 410 core
// shader_check --variants fixture: valid without defines, invalid with BROKEN (line 8), as a
// branch only one define set compiles can be; broken.log records both.
out vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
#ifdef BROKEN
  fragColor = vec4(undefinedInVariant);
#endif
}

#version 410 core
// Deliberately invalid: shader_check must reject it and report line 8 of THIS file, which is
// only right if the #line directive after the include below restores the numbering.
#include "include/sample_common.glsl"

out vec4 fragColor;
void main() {
  fragColor = vec4(undeclaredColor, saturate(1.0));
}

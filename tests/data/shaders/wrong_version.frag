#version 330 core
// Valid GLSL 3.30, but the course requires 410 core on the first line: shader_check must refuse.
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }

#version 410 core
// The floor of a frame's cost (SHADOWLAB_FLOOR_SHADER=1; make bench's frames table): every fragment
// shader of a lesson is replaced by this one, which writes a constant. What remains is the geometry,
// the rasterisation, the depth test and the draw calls: what no shader work can take away.
layout(location = 0) out vec4 fragColor;
void main() { fragColor = vec4(0.5, 0.5, 0.5, 1.0); }

#version 410 core
// No shadows (common/technique/no_shadows): every light reaches every point, V = 1, as in
// lesson 01. The smallest visibility shader a technique can link into the lit pass.
float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  return 1.0;
}

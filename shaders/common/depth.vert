#version 410 core
// The depth pass of every shadow map ([Boreskov2005]): the scene seen from the light, depth only, for
// every light camera of every technique (spot, fitted directional, cube faces; common/technique/casters).
layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec2 aUv;

uniform mat4 uLightViewProj;  // P_light * V_light
uniform mat4 uModel;

out vec2 vUv;

void main() {
  vUv = aUv;
  gl_Position = uLightViewProj * uModel * vec4(aPosition, 1.0);
}

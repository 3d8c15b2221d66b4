#version 410 core
// Pass 2 ([Boreskov2005]): the scene from the eye. The texture matrix
//   T = translate(0.5) * scale(0.5) * P_light * V_light
// takes the world position to shadow-map coordinates (s, t, r, q); the fragment shader divides.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in float aCpuVisibility;  // compare=cpu_vertex: V from the CPU lookup

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;
uniform mat4 uTextureMatrix;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
out vec4 vShadow;
out float vCpuVisibility;
invariant gl_Position;  // the depth pre-pass runs this shader too: depths must match bit for bit

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vUv = aUv;
  vShadow = uTextureMatrix * world;
  vCpuVisibility = aCpuVisibility;
  gl_Position = uViewProj * world;
}

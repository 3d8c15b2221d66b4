#version 410 core
// Lesson 04, passes 1 and 3: the scene. The depth/ambient pass and every light's lit pass draw the
// same triangles with this shader; the lit pass tests depth EQUAL, so gl_Position must come out
// bit for bit the same each time: `invariant`.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
invariant gl_Position;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vUv = aUv;
  gl_Position = uViewProj * world;
}

#version 410 core
// Lesson 06, pass 1: the surface. The object-space position goes to the fragment shader, which
// projects it to texture coordinates (planar, cylindrical, spherical) or uses the mesh's own uvs.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;

out vec3 vObjectPos;
out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vObjectPos = aPosition;
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vUv = aUv;
  gl_Position = uViewProj * world;
}

#version 410 core
// The scene from a camera (the eye, or the god view's), for every lit pass of the technique layer:
// only world data goes down; shadow coordinates are computed per fragment by the technique (a
// normal offset moves the lookup point first). Techniques that draw the same triangles several
// times with depth EQUAL (stencil volumes) need gl_Position bit for bit the same: `invariant`.
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

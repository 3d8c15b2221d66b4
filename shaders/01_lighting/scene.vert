#version 410 core
// Lesson 01, pass 1: the scene. World-space position and normal go to the fragment shader, which
// evaluates the illumination model per pixel; the CPU path (impl=student) sends a per-vertex colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec3 aColor;  // CPU-shaded colour (vertex_cpu shading only)

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
out vec3 vColor;
out vec4 vClip;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPos = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vUv = aUv;
  vColor = aColor;
  vClip = uViewProj * world;
  gl_Position = vClip;
}

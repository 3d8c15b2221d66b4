#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), pass 2 (GPU silhouettes):
// world positions for the geometry shader, which finds the silhouette from triangle adjacency and
// extrudes it.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
out vec3 vWorld;
void main() {
  vWorld = (uModel * vec4(aPosition, 1.0)).xyz;
  gl_Position = vec4(vWorld, 1.0);
}

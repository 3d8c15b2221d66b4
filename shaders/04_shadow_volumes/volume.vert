#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), pass 2 (CPU silhouettes):
// the volume's triangles in world space. w = 1: a point on the caster; w = 0: the same point pushed
// to infinity away from the light, the direction P * L.w - L.xyz with w = 0 (for the sun, L =
// (-direction, 0), simply its direction).
layout(location = 0) in vec4 aPosition;

uniform mat4 uViewProj;
uniform vec4 uLight;  // (position, 1) or (-direction, 0), world space

void main() {
  vec3 p = aPosition.xyz;
  gl_Position = aPosition.w != 0.0 ? uViewProj * vec4(p, 1.0) : uViewProj * vec4(p * uLight.w - uLight.xyz, 0.0);
}

#version 410 core
// Sample vertex shader for shader_check's own tests: world-space position, normal and the
// position in the light's clip space for the shadow-map lookup.
#include "include/sample_common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 model;
uniform mat4 viewProjection;
uniform mat4 lightViewProjection;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 lightClip;

void main() {
  vec4 world = model * vec4(inPosition, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(model) * inNormal;
  lightClip = lightViewProjection * world;
  gl_Position = viewProjection * world;
}

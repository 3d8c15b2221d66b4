#version 410 core
// Sample fragment shader for shader_check's own tests: Lambert shading under one point light,
// darkened by a shadow-map lookup. Includes the common helpers twice (directly and through
// sample_shadow.glsl), which only compiles if the include-once rule works.
#include "include/sample_common.glsl"
#include "include/sample_shadow.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightClip;

uniform vec3 lightPosition;
uniform vec3 lightColor;
uniform sampler2D shadowMap;

out vec4 fragColor;

void main() {
  vec3 n = normalize(worldNormal);
  vec3 l = normalize(lightPosition - worldPosition);
  float lit = shadowFactor(shadowMap, lightClip, 0.005);
  vec3 color = lightColor * saturate(dot(n, l)) / kPi * lit;
  fragColor = vec4(color, 1.0);
}

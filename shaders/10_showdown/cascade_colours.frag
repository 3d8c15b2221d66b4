#version 410 core
// The cascade-colouring view of cascaded shadow maps (lessons/10_showdown/cascades, view=cascades):
// the scene tinted by the cascade of light 0 that shades each point (red, green, blue, yellow near
// to far; a blend band shows as the mix of two), lit by that light alone with its V, so the split
// distances, the band and the shadows read in one picture. Linked with shadow_cascades.frag.
#include "common/light.glsl"
#include "common/measure.glsl"

float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords);
int cascadeOf(int light, vec3 worldPos, out float nextWeight);

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform Light uLights[MAX_LIGHTS];
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform float uAlphaCutoff;

layout(location = 0) out vec4 fragColor;

const vec3 kCascadeColours[4] = vec3[](vec3(1.0, 0.35, 0.3), vec3(0.35, 1.0, 0.35), vec3(0.35, 0.55, 1.0),
                                       vec3(1.0, 0.9, 0.3));

void main() {
  vec3 N = normalize(vNormal);
  vec2 texelCoords;
  float v = shadowVisibility(0, vWorldPos, N, texelCoords);
  float w;
  int k = cascadeOf(0, vWorldPos, w);
  if (uUseTexture && uAlphaCutoff > 0.0 && texture(uTexture, vUv).a < uAlphaCutoff) discard;
  writeMeasurement(vWorldPos, N, v, texelCoords);
  vec3 tint = k < 0 ? vec3(0.6) : mix(kCascadeColours[k], kCascadeColours[min(k + 1, 3)], w);
  Light l = uLights[0];
  float lambert = l.kind == LIGHT_DIRECTIONAL ? max(dot(N, -l.direction), 0.0) : max(dot(N, normalize(l.position - vWorldPos)), 0.0);
  fragColor = vec4(pow(tint * (0.3 + 0.7 * v * lambert), vec3(1.0 / 2.2)), 1.0);
}

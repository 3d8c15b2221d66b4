#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), pass 3: one light, added
// where the stencil count is 0 (V = 1 there, by the stencil test; pixels in shadow never run this
// shader). Blended additively over the ambient pass, in linear light: the frame holds display-
// encoded colour, so the sum is re-encoded (see below).
#include "common/lighting.glsl"
#include "common/measure.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform Light uLight;
uniform vec3 uEye;
uniform vec3 uAlbedo;
uniform float uSpecular;
uniform float uShininess;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform bool uTwoSided;

layout(location = 0) out vec4 fragColor;

// Specialised per light kind (LIGHT_KIND k, from the technique): the kind's branches fold away.
Light passLight() {
  Light l = uLight;
#ifdef LIGHT_KIND
  l.kind = LIGHT_KIND;
#endif
  return l;
}

void main() {
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;
  // Only the measured light's pass reaches the measurement attachments (the others are masked).
  writeMeasurement(vWorldPos, N, 1.0, vec2(0.0));
  vec3 kd = uAlbedo;
  if (uUseTexture) kd *= texture(uTexture, vUv).rgb;
  Light light = passLight();
  vec3 L = toLight(light, vWorldPos);
  vec3 c = lightContribution(N, L, V, incidentRadiance(light, vWorldPos), 1.0, kd, uSpecular, uShininess, true);
  // Additive blending adds display values; the light's own term is encoded on its own. An exact
  // sum in linear light would need a float target; this keeps the frame RGBA8 like every lesson.
  fragColor = vec4(toDisplay(c), 1.0);
}

#version 410 core
// Many point lights (lessons/05_soft_shadows/many_lights; lesson 05): the spherical light replaced by N
// point lights on it, one shadow map each; V is the mean of their N hard comparisons (each with
// hardware 2x2 PCF). N is compiled in (SOFT_SAMPLES): a software renderer pays for every loop trip.
#include "05_soft_shadows/soft_maps.glsl"

#ifndef SOFT_SAMPLES
#define SOFT_SAMPLES 16
#endif

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (uSoftLayer[i] < 0) return 1.0;
  SoftReceiver r = softReceiver(i, worldPos, N);
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r)) return 1.0;
  return softSampledVisibility(i, r.view, softLightViewDirection(i, N), softBias(r), SOFT_SAMPLES);
}

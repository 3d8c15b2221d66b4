#version 410 core
// Bakes one z-slice of the light mesh (lessons/05_soft_shadows/light_mesh): per node, the mean of the
// sample maps' comparisons (the many point lights on the sphere) at the node's position.
#include "05_soft_shadows/soft_maps.glsl"

#ifndef SOFT_SAMPLES
#define SOFT_SAMPLES 16
#endif

uniform vec3 uGridOrigin;
uniform vec3 uGridStep;
uniform float uGridSlice;
uniform int uLight;

layout(location = 0) out vec4 fragColor;

void main() {
  vec3 p = uGridOrigin + uGridStep * vec3(floor(gl_FragCoord.xy), uGridSlice);
  vec3 view = softLightView(uLight, p);
  float z = -view.z;
  if (z <= uSoftDepthRange[uLight].x || z >= uSoftDepthRange[uLight].y) {
    fragColor = vec4(1.0);
    return;
  }
  float texel = 2.0 * z * uSoftTanHalfFov[uLight] / uSoftMapSize;
  fragColor = vec4(softSampledVisibility(uLight, view, vec3(0.0), uSoftBias * texel, SOFT_SAMPLES));
}

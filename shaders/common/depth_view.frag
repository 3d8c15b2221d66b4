#version 410 core
// The shadow map itself, as an image: depth linearised to distance, so near casters are dark and
// the empty far plane is white; orthographic maps are already linear (common/technique/map_view).
#include "common/measure.glsl"

in vec2 vUv;

uniform sampler2D uDepth;     // the depth texture through a raw (non-comparing) sampler
uniform bool uPerspective;    // spot light: window depth is hyperbolic in distance
uniform float uNear, uFar;

layout(location = 0) out vec4 fragColor;

void main() {
  float d = texture(uDepth, vUv).r;
  float lin = d;
  if (uPerspective) {
    float z = 2.0 * d - 1.0;
    float eyeDistance = 2.0 * uNear * uFar / (uFar + uNear - z * (uFar - uNear));
    lin = (eyeDistance - uNear) / (uFar - uNear);
  }
  fragColor = vec4(vec3(sqrt(clamp(lin, 0.0, 1.0))), 1.0);
  writeNoMeasurement();
}

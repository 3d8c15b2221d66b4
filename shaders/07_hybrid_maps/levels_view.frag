#version 410 core
// The hybrid map over the light's view (lessons/07_hybrid_maps/hybrid_maps: drawLevels): each source
// texel coloured by the level it is stored at, darker for nearer depth (linearised for a spot),
// with the stored texels' borders once they are large enough on screen to see. Silhouettes stay
// red (full resolution); floors, roofs and the empty background turn green or blue.
#include "common/measure.glsl"
#include "07_hybrid_maps/hybrid_descent.glsl"
#include "07_hybrid_maps/colours.glsl"

in vec2 vUv;

uniform usampler2D uRoot, uRecords;
uniform int uLevels, uSize;
uniform bool uPerspective;  // a spot's map: window depth linearised for the shading
uniform float uNear, uFar;

layout(location = 0) out vec4 fragColor;

void main() {
  vec2 texel = vUv * float(uSize);
  vec2 perPixel = fwidth(texel);  // source texels per screen pixel (before any branch)
  ivec2 s = clamp(ivec2(floor(texel)), ivec2(0), ivec2(uSize - 1));
  HybridTexel t = hybridDescend(uRoot, uRecords, uLevels, s);
  float scale = float(1 << t.level);
  vec2 within = fract(texel / scale);
  bool border = max(perPixel.x, perPixel.y) < 0.25 * scale && any(lessThan(within, perPixel / scale));
  float lin = t.depth;
  if (uPerspective) lin = (2.0 * uNear * uFar / ((uFar + uNear) - (2.0 * t.depth - 1.0) * (uFar - uNear)) - uNear) /
                          (uFar - uNear);
  float shade = 0.35 + 0.65 * sqrt(clamp(lin, 0.0, 1.0));
  fragColor = vec4(HYBRID_LEVEL_COLOURS[t.level] * shade * (border ? 0.55 : 1.0), 1.0);
  writeNoMeasurement();
}

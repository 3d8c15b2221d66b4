#version 410 core
// One direction of a separable Gaussian blur of a filterable shadow map (common/technique/
// filterable_maps): 2 uRadius + 1 taps along uDirection (one texel), sigma = uRadius / 2. Moments
// and exponentials may be averaged; depths may not (that is what PCF is for).
in vec2 vUv;

uniform sampler2D uSource;
uniform vec2 uDirection;  // (1 / width, 0) or (0, 1 / height)
uniform int uRadius;

layout(location = 0) out vec4 fragColor;

void main() {
  float sigma = max(float(uRadius) * 0.5, 0.5);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int k = -uRadius; k <= uRadius; ++k) {
    float w = exp(-0.5 * float(k * k) / (sigma * sigma));
    sum += w * texture(uSource, vUv + uDirection * float(k));
    weights += w;
  }
  fragColor = sum / weights;
}

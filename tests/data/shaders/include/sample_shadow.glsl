// Shadow-map lookup for the sample fragment shader. Includes sample_common.glsl itself so it can
// be used alone; the include-once rule keeps a second copy out when the shader includes both.
#include "sample_common.glsl"

// 1 when `lightClip` (the fragment in the light's clip space) is lit, 0 when it is in shadow.
float shadowFactor(sampler2D shadowMap, vec4 lightClip, float bias) {
  vec3 ndc = lightClip.xyz / lightClip.w;
  vec3 uvz = ndc * 0.5 + 0.5;
  float occluder = texture(shadowMap, uvz.xy).r;
  return uvz.z - bias > occluder ? 0.0 : 1.0;
}

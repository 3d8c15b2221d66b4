// The lecture's illumination model with visibility ([Tarantsev-L12]), for every lesson:
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (R_i.V)^pow]
// Mirrors common/algorithms/lighting.cpp (the reference the graders test); keep the two in step.

#include "common/light.glsl"

float attenuationFactor(vec3 c, float d) { return 1.0 / (c.x + c.y * d + c.z * d * d); }

float spotFactor(float cosAngle, float cosInner, float cosOuter) {
  if (cosInner <= cosOuter) return cosAngle >= cosOuter ? 1.0 : 0.0;
  float t = clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Unit vector from p toward the light.
vec3 toLight(Light light, vec3 p) {
  return light.kind == LIGHT_DIRECTIONAL ? -light.direction : normalize(light.position - p);
}

// f_att, the spot cone and the colour: everything about the light at p but V_i.
vec3 incidentRadiance(Light light, vec3 p) {
  if (!light.enabled) return vec3(0.0);
  if (light.kind == LIGHT_DIRECTIONAL) return light.color;
  vec3 r = light.color * attenuationFactor(light.attenuation, length(light.position - p));
  if (light.kind == LIGHT_SPOT) r *= spotFactor(dot(light.direction, -toLight(light, p)), light.cosInner, light.cosOuter);
  return r;
}

// V f_att I [kd (N.L) + ks (R.V)^pow]; `blinn` swaps (R.V) for Blinn's (N.H).
vec3 lightContribution(vec3 N, vec3 L, vec3 V, vec3 radiance, float visibility, vec3 kd, float ks,
                       float shininess, bool blinn) {
  float NdotL = dot(N, L);
  if (NdotL <= 0.0) return vec3(0.0);
  float s = blinn ? max(dot(N, normalize(L + V)), 0.0) : max(dot(reflect(-L, N), V), 0.0);
  return visibility * radiance * (kd * NdotL + vec3(ks * pow(s, shininess)));
}

// Linear to display: the framebuffers are plain RGBA8, so encode sRGB here.
vec3 toDisplay(vec3 linear) { return pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2)); }

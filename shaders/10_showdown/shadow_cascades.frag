#version 410 core
// Cascaded shadow maps' visibility (lessons/10_showdown/cascades), linked into every lit program that
// serves them (shaders/common/scene.frag declares the function). The view's depth range is cut into
// 1 to 4 slices by the practical split scheme; slice k has its own orthographic map, layer k of the
// light's array texture (the projective maps' storage and lookup, 08_psm/projective_maps.glsl). A
// point takes the cascade its view depth falls in; within the blend band at a cascade's far end the
// next cascade's lookup is mixed in (shadow::cascadeAt in common/algorithms/cascades.cpp mirrors
// cascadeAt in 10_showdown/exercises_reference.glsl: keep the two in step).
#include "08_psm/projective_maps.glsl"

uniform vec4 uCsmViewZ;            // the viewer's view-matrix row of z: view depth = -dot(row, (p, 1))
uniform float uCsmNear;            // where cascade 0 starts
uniform vec4 uCsmFar[PSM_LIGHTS];  // where cascades 0..3 end (uPsmLayers[light] of them)
uniform float uCsmBand;            // the blend band: this fraction of a cascade's depth range at its far end

// cascadeAt(light, depth, out nextWeight): the cascade of a view depth and the next one's weight in
// the blend band: exercise 10.4 (GLSL), exercise 10.3's answer in the shader. The student's with
// impl=student in lesson 10 (the cascades' shaderDefines() add SHADOWLAB_STUDENT_CASCADES), else the
// reference (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_CASCADES
#include "10_showdown/exercises.glsl"
#else
#include "10_showdown/exercises_reference.glsl"
#endif

// The cascade of a surface point (for the cascade-colouring view, shaders/10_showdown/cascade_colours.frag).
int cascadeOf(int light, vec3 worldPos, out float nextWeight) {
  nextWeight = 0.0;
  if (light >= PSM_LIGHTS) return -1;
  return cascadeAt(light, -dot(uCsmViewZ, vec4(worldPos, 1.0)), nextWeight);
}

float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  vec3 dPdx = dFdx(worldPos), dPdy = dFdy(worldPos);  // the receiver plane's, before any branch
  float w;
  int k = cascadeOf(light, worldPos, w);
  if (k < 0) return 1.0;  // no cascade covers the point (light off, or beyond the last): lit
  // The point's cascade k, then in the blend band the next one mixed in: a loop of (at most) two
  // trips from the pixel's own k rather than an `if`, so that only pixels in a band pay the second
  // lookup (docs/performance.md, "Work few pixels need: in a loop's second trip").
  float v = 1.0;
  for (int j = k; j <= k + 1; ++j) {
    vec2 coords;
    float vj = projectiveLookup(light, j, worldPos, N, dPdx, dPdy, false, coords);
    if (j == k) {
      v = vj;
      texelCoords = coords;
      if (!(w > 0.0)) break;
    } else {
      v = mix(v, vj, w);
    }
  }
  return v;
}

// The aliasing measurement's Jacobian (SHADOW_TEXEL_JACOBIAN, scene.frag): through the pixel's own
// cascade. dFdx of texelCoords would difference two cascades' maps where a 2x2 quad straddles a
// split, and the measured m would spike to the jump between the maps along every seam.
vec4 shadowTexelJacobian(int light, vec3 worldPos, vec3 dPdx, vec3 dPdy) {
  float w;
  int k = cascadeOf(light, worldPos, w);
  return k < 0 ? vec4(0.0) : projectiveTexelJacobian(light, k, worldPos, dPdx, dPdy);
}

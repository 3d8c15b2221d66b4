#version 410 core
// Percentage-closer filtering of the map from the sphere's centre (common/technique/pcss; lesson
// 05): Poisson taps rotated per pixel over a disk of
//   PCF   a fixed radius (uFixedRadius texels): the baseline, one penumbra width everywhere
//   PCSS  (Fernando 2005, #define PCSS) a radius from the blockers: search the region where
//         something can hide part of the sphere, average the blockers' depth d_b, and filter over
//         w = (d_r - d_b) / d_b * R, in uv w / (2 d_r tan(fov/2)) (soft::pcssFilterRadiusUv)
// A uniform disk of taps over a straight shadow edge averages to the disk's visible fraction:
// A_frac itself. Each tap compares against the receiver's plane there (no acne from wide kernels).
#include "common/soft_maps.glsl"

#ifndef SEARCH_TAPS
#define SEARCH_TAPS 16
#endif

uniform vec2 uSearchTaps[SEARCH_TAPS];  // Poisson disks in the unit disk (soft::poissonDisk)
#ifdef PCSS
// The filter's count a uniform, not compiled in, so that its loop stays a loop: pixels whose search
// found no blocker skip it (SOFT_MAX_TAPS in soft_maps.glsl). PCF filters every pixel: compiled in.
uniform vec2 uFilterTaps[SOFT_MAX_TAPS];  // the first uFilterCount
uniform int uFilterCount;
#define FILTER_COUNT uFilterCount
#else
#ifndef FILTER_TAPS
#define FILTER_TAPS 16
#endif
uniform vec2 uFilterTaps[FILTER_TAPS];
#define FILTER_COUNT FILTER_TAPS
#endif
uniform float uFixedRadius;    // PCF: texels
uniform float uMaxSearch;      // PCSS: the search region's cap, in uv
uniform float uMinFilter;      // PCSS: the smallest filter radius, texels (a contact stays antialiased)

// The blocker search, blockerSearch: exercise 05.6 (GLSL). The student's with impl=student in
// lesson 05 (the technique's shaderDefines() add SHADOWLAB_STUDENT_PCSS), else the reference
// (sealed in the student handout).
#ifdef SHADOWLAB_STUDENT_PCSS
#include "05_soft_shadows/exercises.glsl"
#else
#include "05_soft_shadows/exercises_reference.glsl"
#endif

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  SoftReceiver r = softReceiver(i, worldPos, N);
  vec3 dx = dFdx(vec3(r.uv, r.z)), dy = dFdy(vec3(r.uv, r.z));  // uniform control flow: before any return
  if (uSoftLayer[i] < 0) return 1.0;
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r)) return 1.0;
  vec2 plane = softReceiverPlane(dx, dy, r, i);
  float bias = softBias(r);
  float a = softRotation(gl_FragCoord.xy);
  mat2 turn = softTapTurn(a);
#ifdef PCSS
  // The region for a blocker at the nearest caster (no blocker is nearer), not on the near plane.
  float near = uSoftCasterNear[i], tanHalf = uSoftTanHalfFov[i], R = uSoftRadius[i];
  float search = softPcssSearchUv(R, r.z, near, tanHalf, uMaxSearch);
  vec2 found = blockerSearch(i, r.uv, r.z, plane, bias, search, turn);  // (mean distance, count)
  // Nothing can hide the light: lit. Where a whole group of pixels returns here, the filter loop
  // below is skipped, by a GPU and by llvmpipe alike, as long as it stays a loop (soft_maps.glsl).
  if (found.y == 0.0) return softHorizon(i, worldPos, N);
  // No "every search tap blocked: umbra" exit (Fernando's): a few taps over leaf cards with holes
  // all land on leaves where the sphere still shows through the holes; the filter decides.
  float zBlocker = found.x;
  float radius = max(softPcssRadiusUv(R, r.z, zBlocker, tanHalf), uMinFilter / uSoftMapSize);
#else
  float radius = uFixedRadius / uSoftMapSize;
#endif
  float v = 0.0;
  for (int k = 0; k < FILTER_COUNT; ++k) {
    vec2 o = turn * uFilterTaps[k] * radius;
    v += softCompare(i, 0, r.uv + o, r.z + dot(plane, o) - bias);
  }
  return v / float(FILTER_COUNT) * softHorizon(i, worldPos, N);
}

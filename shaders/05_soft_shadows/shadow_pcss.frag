#version 410 core
// Percentage-closer filtering of the map from the sphere's centre (lessons/05_soft_shadows/pcss; lesson
// 05): Poisson taps rotated per pixel over a disk of
//   PCF   a fixed radius (uFixedRadius texels): the baseline, one penumbra width everywhere
//   PCSS  (Fernando 2005, #define PCSS) a radius from the blockers: search the region where
//         something can hide part of the sphere, average the blockers' depth d_b, and filter over
//         w = (d_r - d_b) / d_b * R, in uv w / (2 d_r tan(fov/2)) (soft::pcssFilterRadiusUv)
// A uniform disk of taps over a straight shadow edge averages to the disk's visible fraction:
// A_frac itself. Each tap compares against the receiver's plane there (no acne from wide kernels).
//   QUAD_SEARCH  the four pixels of a 2x2 quad share one blocker search: each reads SEARCH_TAPS
//                taps (a quarter of the search, soft::quarterTurnDisk) turned by its own quarter
//                turn, and fine derivatives pass the blockers' sums round the quad. The search
//                estimates one depth for a penumbra many pixels wide: a quad's is as good, at a
//                quarter of the reads (on llvmpipe every pixel pays every tap).
#ifdef QUAD_SEARCH
#extension GL_ARB_derivative_control : require
#endif
#include "05_soft_shadows/soft_maps.glsl"

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
// (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_PCSS
#include "05_soft_shadows/exercises.glsl"
#else
#include "05_soft_shadows/exercises_reference.glsl"
#endif

#ifdef QUAD_SEARCH
// Where this pixel sits in its 2x2 quad, (0 or 1, 0 or 1): the parity of its coordinates, read
// through the fine derivative of that parity (+1 where the quad starts on an even coordinate, -1
// where it starts on an odd one), so it holds however the driver aligns its quads.
vec2 quadCorner() {
  vec2 s = mod(floor(gl_FragCoord.xy), 2.0);
  vec2 ds = vec2(dFdxFine(s.x), dFdyFine(s.y));
  return vec2((s.x - 0.5) * ds.x < 0.0 ? 0.0 : 1.0, (s.y - 0.5) * ds.y < 0.0 ? 0.0 : 1.0);
}

// The sum of v over the pixel's quad: its row neighbour is v + dFdxFine(v) from the left pixel,
// v - dFdxFine(v) from the right one; the same down the columns for the pair sums.
vec2 quadSum(vec2 v, vec2 corner) {
  vec2 pair = 2.0 * v + (corner.x == 0.0 ? 1.0 : -1.0) * dFdxFine(v);
  return 2.0 * pair + (corner.y == 0.0 ? 1.0 : -1.0) * dFdyFine(pair);
}
#endif

#ifdef PCSS
// The blocker search (mean distance, count): the pixel's own, or its quad's (QUAD_SEARCH). Called
// in uniform control flow: the quad's derivatives need every pixel of it.
vec2 pcssSearch(int i, SoftReceiver r, vec2 plane, float bias, float radius, mat2 turn) {
#ifdef QUAD_SEARCH
  vec2 corner = quadCorner();
  // One angle for the quad (from its first pixel), a quarter turn more for each of its pixels.
  float a = softRotation(gl_FragCoord.xy - corner) + 1.57079632679 * (corner.x + 2.0 * corner.y);
  vec2 own = blockerSearch(i, r.uv, r.z, plane, bias, radius, softTapTurn(a));
  if (softOutside(i, r)) own = vec2(0.0);  // beyond the map's depth range: nothing to share
  vec2 quad = quadSum(vec2(own.x * own.y, own.y), corner);  // (sum of distances, count)
  return quad.y < 0.5 ? vec2(0.0) : vec2(quad.x / quad.y, quad.y);
#else
  return blockerSearch(i, r.uv, r.z, plane, bias, radius, turn);
#endif
}
#endif

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  SoftReceiver r = softReceiver(i, worldPos, N);
  vec3 dx = dFdx(vec3(r.uv, r.z)), dy = dFdy(vec3(r.uv, r.z));  // uniform control flow: before any return
  if (uSoftLayer[i] < 0) return 1.0;
  texelCoords = r.uv * uSoftMapSize;
  vec2 plane = softReceiverPlane(dx, dy, r, i);
  float bias = softBias(r);
  float a = softRotation(gl_FragCoord.xy);
  mat2 turn = softTapTurn(a);
#ifdef PCSS
  // The region for a blocker at the nearest caster (no blocker is nearer), not on the near plane.
  float near = uSoftCasterNear[i], tanHalf = uSoftTanHalfFov[i], R = uSoftRadius[i];
  float search = softPcssSearchUv(R, r.z, near, tanHalf, uMaxSearch);
  vec2 found = pcssSearch(i, r, plane, bias, search, turn);  // before the return below: see pcssSearch
#endif
  if (softOutside(i, r)) return 1.0;
#ifdef PCSS
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

#version 410 core
// Single-sample soft shadows (lessons/05_soft_shadows/single_sample; lesson 05): one map from the sphere's
// centre, its hard shadow kept as the umbra, a penumbra added only OUTSIDE it:
//   Parker et al. 1998: the caster grows an outer hull whose thickness at a blocker is the light
//     cone's radius there, R (z_r - z_b) / z_r; a lit point whose ray to the centre passes delta
//     from the caster gets profile(2 delta / thickness - 1). On a map: the nearest blocker texels
//     around the receiver's uv; delta and the thickness in uv (soft::outerPenumbra).
//   Haines 2001 (#define HAINES): soft planar shadows with plateaus. Only the receiving plane
//     (y = uPlaneHeight, facing up) gets a penumbra: from each blocker texel's shadow on the plane,
//     a plateau rising over 2r, r = d / (n.L) * R / D of that blocker (soft::plateau).
// Both miss the inner half of the penumbra (inside the hard shadow): the umbra comes out too big.
// profile: A_frac or its linear approximation (#define LINEAR_PROFILE).
#include "05_soft_shadows/soft_maps.glsl"

#ifndef SEARCH_TAPS
#define SEARCH_TAPS 24
#endif
#ifdef LINEAR_PROFILE
const bool LINEAR = true;
#else
const bool LINEAR = false;
#endif

uniform vec2 uSearchTaps[SEARCH_TAPS];
uniform float uMaxSearch;    // the search region's cap, uv
uniform mat4 uSoftViewInverse[MAX_LIGHTS];
uniform float uPlaneHeight;  // Haines: the receiving plane y = h
uniform float uPlaneTolerance;

// PCSS's blocker search, blockerSearch (exercise 05.6's reference, withheld from the student handout).
#include "05_soft_shadows/exercises_reference.glsl"

#ifdef HAINES
// The plateau of one blocker texel (uv + o at distance zb) at the receiver p on the plane.
float plateauOf(int i, vec2 uv, float zb, vec3 p) {
  float tanHalf = uSoftTanHalfFov[i];
  vec3 bView = vec3((uv - 0.5) * 2.0 * zb * tanHalf, -zb);
  vec3 b = (uSoftViewInverse[i] * vec4(softUnturn(i, bView), 1.0)).xyz;
  vec3 L = uLights[i].position;
  if (b.y <= uPlaneHeight + 1e-3 || L.y <= b.y) return 1.0;
  vec3 shadowPoint = L + (b - L) * ((uPlaneHeight - L.y) / (b.y - L.y));
  float d = length(b - shadowPoint), D = length(b - L);
  float nDotL = max((L.y - shadowPoint.y) / length(L - shadowPoint), 1e-3);
  float halfWidth = softPenumbraHalfWidth(d, nDotL, uSoftRadius[i], D);
  if (halfWidth <= 0.0) return 1.0;
  return softProfile(length(p - shadowPoint) / halfWidth - 1.0, LINEAR);
}
#endif

// Step 1, as PCSS's blocker search: the mean depth of the blockers in the search region, or -1.
float meanBlockerDepth(int i, SoftReceiver r, vec2 plane, float bias, float search, mat2 turn) {
  vec2 found = blockerSearch(i, r.uv, r.z, plane, bias, search, turn);  // (mean distance, count)
  return found.y > 0.0 ? found.x : -1.0;
}

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  SoftReceiver r = softReceiver(i, worldPos, N);
  vec3 dx = dFdx(vec3(r.uv, r.z)), dy = dFdy(vec3(r.uv, r.z));
  if (uSoftLayer[i] < 0) return 1.0;
  texelCoords = r.uv * uSoftMapSize;
  if (softOutside(i, r)) return 1.0;
  vec2 plane = softReceiverPlane(dx, dy, r, i);
  float bias = softBias(r);
  float hard = softCompare(i, 0, r.uv, r.z - bias);
  if (hard <= 0.0) return 0.0;  // the hard shadow is the umbra
#ifdef HAINES
  if (N.y < 0.99 || abs(worldPos.y - uPlaneHeight) > uPlaneTolerance)
    return hard * softHorizon(i, worldPos, N);  // not the plane: the hard shadow
#endif
  float near = uSoftDepthRange[i].x, tanHalf = uSoftTanHalfFov[i], R = uSoftRadius[i];
  float search = softPcssSearchUv(R, r.z, near, tanHalf, uMaxSearch);
  float a = softRotation(gl_FragCoord.xy);
  mat2 turn = softTapTurn(a);
  float zMean = meanBlockerDepth(i, r, plane, bias, search, turn);
  if (zMean <= 0.0) return hard * softHorizon(i, worldPos, N);
  // Step 2: the taps again, over the penumbra these blockers can throw (the hull's thickness at
  // their mean depth; for plateaus the full width 2r, stretched by 1 / (n.L) on the plane), so
  // they are dense where the nearest blocker is.
  float hull = softPcssRadiusUv(R, r.z, zMean, tanHalf);
#ifdef HAINES
  hull *= 2.0 / max(N.y * normalize(uLights[i].position - worldPos).y, 0.2);
#endif
  float v = 1.0;
  for (int k = 0; k < SEARCH_TAPS; ++k) {
    vec2 o = turn * uSearchTaps[k] * hull;
    float zb = softDepthAt(i, 0, r.uv + o);
    if (zb >= r.z + dot(plane, o) - bias) continue;  // not a blocker
#ifdef HAINES
    v = min(v, plateauOf(i, r.uv + o, zb, worldPos));
#else
    float thickness = softPcssRadiusUv(R, r.z, zb, tanHalf);  // the hull at this blocker, uv
    v = min(v, thickness > 0.0 ? softProfile(2.0 * length(o) / thickness - 1.0, LINEAR) : 1.0);
#endif
  }
  return hard * v * softHorizon(i, worldPos, N);
}

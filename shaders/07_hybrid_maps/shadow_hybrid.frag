#version 410 core
// The hybrid-resolution shadow map's visibility (lessons/07_hybrid_maps/hybrid_maps; lesson 07; Li, Yang,
// Zhao, Chen, Chinese Optics 9(1), 2016, Algorithm 2), linked into every lit program that serves
// it. Per light a directional (orthographic) or spot (perspective) map: project into the light's
// space, read the root texel, follow the index down to the finest stored texel, compare. The bias
// grows with the level read: a texel merged over 2^level source texels stores their mean, which a
// tilted receiver inside it is up to 2^level times farther from (levelBias). Filters (HYBRID_FILTER, from the
// technique's shaderDefines): 0 nearest, 1 bilinear 2x2 (four descents, bilinear weights, what
// hardware 2x2 PCF does on a standard map), 2 N x N box (each tap descends).
#include "common/light.glsl"
#include "common/shadow_bias.glsl"
#include "07_hybrid_maps/hybrid_descent.glsl"

#ifndef HYBRID_FILTER
#define HYBRID_FILTER 0
#endif

const int HYBRID_NONE = 0, HYBRID_ORTHO = 1, HYBRID_PERSPECTIVE = 2;

uniform Light uLights[MAX_LIGHTS];
uniform int uHybridType[MAX_LIGHTS];     // HYBRID_NONE: no map (off, or a point light): lit
uniform mat4 uHybridMatrix[MAX_LIGHTS];  // the texture matrix: world -> [0,1]^3
uniform float uHybridTexel[MAX_LIGHTS];  // ortho: a source texel's world size; perspective: 2 tan(fov/2) / N
uniform int uHybridSize[MAX_LIGHTS];     // N, source texels per side
uniform int uHybridLevels[MAX_LIGHTS];
uniform usampler2D uHybridRoot[MAX_LIGHTS];
uniform usampler2D uHybridRecords[MAX_LIGHTS];
uniform int uPcfSize;  // N of the N x N box (odd)

// levelBias(cosTheta, level), the bias for a texel stored at `level` (hybrid::levelBias), is in
// common/shadow_bias_slope.glsl (through shadow_bias.glsl): at level 0 it is exercise 03.1's
// slope-scaled bias, so it is sealed in the student handout with it.

// GLSL ES 3.00 (WebGL2) indexes an array of samplers with constants only: a switch there.
HybridTexel hybridDescendLight(int i, ivec2 s) {
#ifdef SHADOWLAB_GLES
  switch (i) {
    case 0: return hybridDescend(uHybridRoot[0], uHybridRecords[0], uHybridLevels[0], s);
    case 1: return hybridDescend(uHybridRoot[1], uHybridRecords[1], uHybridLevels[1], s);
    case 2: return hybridDescend(uHybridRoot[2], uHybridRecords[2], uHybridLevels[2], s);
    default: return hybridDescend(uHybridRoot[3], uHybridRecords[3], uHybridLevels[3], s);
  }
#else
  return hybridDescend(uHybridRoot[i], uHybridRecords[i], uHybridLevels[i], s);
#endif
}

// One comparison at source texel s: lit (1) when depth - levelBias <= the stored depth; outside the
// map, lit (a standard map's border of depth 1).
float hybridTap(int i, ivec2 s, float depth, float cosTheta, inout int level, inout int steps) {
  int size = uHybridSize[i];
  if (s.x < 0 || s.y < 0 || s.x >= size || s.y >= size) return 1.0;
  HybridTexel t = hybridDescendLight(i, s);
  level = min(level, t.level);
  steps = max(steps, t.steps);
  return depth - levelBias(cosTheta, t.level) <= t.depth ? 1.0 : 0.0;
}

// V of light i, with the finest level any tap read (-1 outside the map) and the most steps a tap
// took. texelCoords: source texels (uv * N), whatever level a tap reached, so the aliasing factor m
// counts source texels; where the map merged, a stored texel is 2^level of them.
float hybridVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords, out int level, out int steps) {
  texelCoords = vec2(0.0);
  level = -1;
  steps = 0;
  int type = uHybridType[i];
  if (type == HYBRID_NONE) return 1.0;
  float cosTheta;
  vec3 q = normalOffsetPoint(uLights[i], type == HYBRID_PERSPECTIVE, uHybridTexel[i], worldPos, N, cosTheta);
  vec4 h = uHybridMatrix[i] * vec4(q, 1.0);
  vec3 p = h.w > 0.0 ? h.xyz / h.w : vec3(0.5, 0.5, 2.0);  // behind a spot: nothing known, lit
  float size = float(uHybridSize[i]);
  texelCoords = p.xy * size;
  if (p.z > 1.0) return 1.0;
  level = 99;  // lowered by every tap that lands in the map
  float v;
#if HYBRID_FILTER == 0
  v = hybridTap(i, ivec2(floor(texelCoords)), p.z, cosTheta, level, steps);
#elif HYBRID_FILTER == 1
  vec2 t = texelCoords - 0.5;
  ivec2 s = ivec2(floor(t));
  vec2 f = t - floor(t);
  float v00 = hybridTap(i, s, p.z, cosTheta, level, steps), v10 = hybridTap(i, s + ivec2(1, 0), p.z, cosTheta, level, steps);
  float v01 = hybridTap(i, s + ivec2(0, 1), p.z, cosTheta, level, steps), v11 = hybridTap(i, s + ivec2(1, 1), p.z, cosTheta, level, steps);
  v = mix(mix(v00, v10, f.x), mix(v01, v11, f.x), f.y);
#else
  ivec2 s = ivec2(floor(texelCoords));
  int h2 = uPcfSize / 2;
  float sum = 0.0;
  for (int y = -h2; y <= h2; ++y)
    for (int x = -h2; x <= h2; ++x) sum += hybridTap(i, s + ivec2(x, y), p.z, cosTheta, level, steps);
  v = sum / float(uPcfSize * uPcfSize);
#endif
  if (level == 99) level = -1;
  return v;
}

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  int level, steps;
  return hybridVisibility(i, worldPos, N, texelCoords, level, steps);
}

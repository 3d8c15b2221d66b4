#version 410 core
// One level of the merge sweep (Li et al. 2016, §2.2; common/algorithms/hybrid_map: mergeBlock,
// sweepLevel and the count pyramid's first levels), one fragment per texel of level k: the 2x2
// block of level k-1 under it merges into its mean when every child passes the criterion, else it
// is kept and owns a record of its four children. Bit for bit what the CPU reference computes:
// the same float operations in the same order, `precise` so none is fused or reordered.
uniform sampler2D uChildren;      // level k-1: the depth map (k = 1) or its merge grid (mean, or -1)
uniform usampler2D uChildCounts;  // level k-1's records per subtree (k >= 2)
uniform int uLevel;               // k
uniform int uChildSize;           // level k-1 texels a side
uniform int uCriterion;           // 0 window depth, 1 linear depth, 2 the depth's derivative
uniform float uEps0, uMaxSlope;
uniform bool uPerspective;
uniform float uNear, uFar, uTexel;  // hybrid::DepthSpace

layout(location = 0) out float outValue;  // the mean, or -1: kept
layout(location = 1) out uvec4 outCount;  // records in the subtree: total, then at levels 1, 2, 3

float linearDepth(float d) {  // hybrid::linearDepth
  precise float range = uFar - uNear;
  if (!uPerspective) return d * range;
  precise float ndc = 2.0 * d - 1.0;
  precise float z = (2.0 * uNear * uFar) / ((uFar + uNear) - ndc * range);
  return z;
}

float mean4(vec4 d) {
  precise float m = ((d.x + d.y) + (d.z + d.w)) * 0.25;
  return m;
}

bool within(vec4 d, float m, vec4 allowed) {
  precise vec4 off = abs(vec4(m) - d);
  return all(lessThanEqual(off, allowed));
}

// hybrid::mergeBlock
bool mergeBlock(vec4 d, out float mean) {
  mean = mean4(d);
  if (!all(greaterThanEqual(d, vec4(0.0)))) return false;  // a kept child (or NaN)
  if (uCriterion == 0) {
    precise vec4 allowed = uEps0 * d;
    return within(d, mean, allowed);
  }
  vec4 z = vec4(linearDepth(d.x), linearDepth(d.y), linearDepth(d.z), linearDepth(d.w));
  float mz = mean4(z);
  if (uCriterion == 1) {
    precise vec4 allowed = uEps0 * z;
    return within(z, mz, allowed);
  }
  precise float texels = float(1 << (uLevel - 1));
  precise float width = (uPerspective ? mz * uTexel : uTexel) * texels;
  precise float allowed = 0.5 * uMaxSlope * width;
  return within(z, mz, vec4(allowed));
}

uvec4 childCount(ivec2 c) {
  if (uLevel == 1 || c.x >= uChildSize || c.y >= uChildSize) return uvec4(0u);
  return texelFetch(uChildCounts, c, 0);
}

void main() {
  ivec2 c = 2 * ivec2(gl_FragCoord.xy);
  bool inside = c.x + 1 < uChildSize && c.y + 1 < uChildSize;  // else a block cut by the border: kept
  float mean = 0.0;
  if (inside) {
    vec4 d = vec4(texelFetch(uChildren, c, 0).r, texelFetch(uChildren, c + ivec2(1, 0), 0).r,
                  texelFetch(uChildren, c + ivec2(0, 1), 0).r, texelFetch(uChildren, c + ivec2(1, 1), 0).r);
    if (mergeBlock(d, mean)) {
      outValue = mean;
      outCount = uvec4(0u);
      return;
    }
  }
  uvec4 sum = childCount(c) + childCount(c + ivec2(1, 0)) + childCount(c + ivec2(0, 1)) + childCount(c + ivec2(1, 1));
  sum.x += 1u;
  if (uLevel <= 3) sum[uLevel] += 1u;
  outValue = -1.0;
  outCount = sum;
}

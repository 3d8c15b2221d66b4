// The slope-scaled depth bias of every 2D shadow map (included by shadow_bias.glsl, which declares
// the uniforms): exercise 03.1's answer in GLSL, sealed in the student handout. Mirrors
// common/algorithms/shadow_math and hybrid_map (levelBias); keep them in step.
float slopeScaledBias(float cosTheta) {  // shadow::slopeScaledBias
  if (cosTheta <= 0.0) return uMaxBias;
  float c = min(cosTheta, 1.0);
  return min(uConstantBias + uSlopeBias * sqrt(1.0 - c * c) / c, uMaxBias);
}

// The hybrid map's bias for a texel stored at `level` (shadow_hybrid.frag): the slope-scaled part
// and its clamp grow with the texel, 2^level source texels wide (a tilted receiver is that much
// farther from the stored mean); the constant part, the depth format's precision, does not.
// Level 0: slopeScaledBias.
float levelBias(float cosTheta, int level) {  // hybrid::levelBias
  float scale = float(1 << level);
  if (cosTheta <= 0.0) return uMaxBias * scale;
  float c = min(cosTheta, 1.0);
  return min(uConstantBias + uSlopeBias * sqrt(1.0 - c * c) / c * scale, uMaxBias * scale);
}

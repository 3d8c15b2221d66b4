// The soft-shadow formulas of lesson 05's exercises in GLSL, shared by soft_maps.glsl and its
// techniques: sealed in the student handout (they are exercises 05.1, 05.2 and 05.3's answers).
// Mirrors common/algorithms/soft_shadows; keep the two in step.

// The lecture's A_frac of t = a / R and its linear approximation.
float softVisibleFraction(float t) {  // soft::visibleFraction
  t = clamp(t, -1.0, 1.0);
  return 0.5 + (t * sqrt(max(1.0 - t * t, 0.0)) + asin(t)) / 3.14159265;
}
float softProfile(float t, bool linearProfile) {  // soft::visibleFractionLinear
  return linearProfile ? 0.5 * (1.0 + clamp(t, -1.0, 1.0)) : softVisibleFraction(t);
}

// The penumbra's half width on a receiver d behind the blocker, light radius R at distance D.
float softPenumbraHalfWidth(float d, float nDotL, float R, float D) {  // soft::penumbraHalfWidth
  return d / nDotL * R / D;
}

// PCSS (Fernando 2005): the filter radius in uv from the mean blocker distance.
float softPcssRadiusUv(float R, float zReceiver, float zBlocker, float tanHalf) {  // soft::pcssFilterRadiusUv
  return R * max(zReceiver - zBlocker, 0.0) / (zBlocker * 2.0 * zReceiver * tanHalf);
}

// The soft-shadow formulas of lesson 05's exercises in GLSL, shared by soft_maps.glsl and its
// techniques: sealed in the student handout (they are exercises 05.1, 05.2, 05.3 and 05.4's answers).
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

// PCSS's search region in uv: the same radius for a blocker on the near plane (the nearest any can
// be), at most maxUv; the operands in the order the techniques always had them.
float softPcssSearchUv(float R, float zReceiver, float zNear, float tanHalf, float maxUv) {  // soft::pcssFilterRadiusUv
  return min(R * max(zReceiver - zNear, 0.0) / (2.0 * tanHalf * zNear * zReceiver), maxUv);
}

// The per-pixel turn of the Poisson taps by the angle a: turn * o is the tap o rotated (exercise
// 05.4's rotation as a matrix).
mat2 softTapTurn(float a) {  // soft::rotateTap
  return mat2(cos(a), sin(a), -sin(a), cos(a));
}

// Shared constants and helpers for the sample shaders (include-only: validated through them).
const float kPi = 3.14159265358979;

float saturate(float x) { return clamp(x, 0.0, 1.0); }

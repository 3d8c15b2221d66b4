// Lesson 10, GLSL exercise: the reference (withheld from the student handout; exercises.glsl says what
// the function does). shadow_cascades.frag includes this file unless SHADOWLAB_STUDENT_CASCADES is
// set; it reads that shader's uniforms. Mirrors shadow::cascadeAt (common/algorithms/cascades.cpp);
// keep them in step.

// The cascade that shades view depth `depth` of light `light` (-1: none), and the weight of the next.
int cascadeAt(int light, float depth, out float nextWeight) {
  nextWeight = 0.0;
  int count = uPsmLayers[light];
  if (count == 0 || depth < uCsmNear || depth > uCsmFar[light][count - 1]) return -1;
  int k = 0;
  while (k < count - 1 && depth > uCsmFar[light][k]) ++k;
  if (k == count - 1 || uCsmBand <= 0.0) return k;
  float zNear = k == 0 ? uCsmNear : uCsmFar[light][k - 1];
  float width = uCsmBand * (uCsmFar[light][k] - zNear);
  float start = uCsmFar[light][k] - width;
  if (depth > start) nextWeight = min((depth - start) / width, 1.0);
  return k;
}

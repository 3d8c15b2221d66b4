#version 410 core
// The visibility of the techniques that warp space before rendering depth: perspective shadow maps
// (lessons/08_psm/psm: the original and the fixes of Kozlov et al., "Perspective Shadow Maps:
// Care and Feeding") and LiSPSM (lessons/09_psm_fixes/lispsm), linked into every lit program that
// serves them (shaders/common/scene.frag declares the function). Per light, up to six maps in one
// array texture: one map, or one per hidden face of the camera's unit cube (fix 3, PSM_FACES).
// Each map's matrix takes the world point to the map's clip space in one projective step, the
// camera's projection included.
#include "08_psm/projective_maps.glsl"

#ifdef PSM_FACES
uniform bool uPsmFaces[PSM_LIGHTS];
uniform mat4 uPsmCamera[PSM_LIGHTS];            // the camera whose unit cube the faces are (maybe slid)
uniform vec4 uPsmPostLight[PSM_LIGHTS];         // the light there: (position, 1) or (direction, 0)
uniform int uPsmLayerOfFace[PSM_LIGHTS * 6];    // faces 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; -1: none

// The hidden face the ray from the light through the point leaves the cube by (for a direction:
// the ray through the point along -direction), cubeFaceLayer: exercise 09.6 (GLSL). The student's
// with impl=student in lesson 09 (the maps' shaderDefines() add SHADOWLAB_STUDENT_PSM_FACES), else
// the reference (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_PSM_FACES
#include "09_psm_fixes/exercises.glsl"
#else
#include "09_psm_fixes/exercises_reference.glsl"
#endif

int faceLayer(int i, vec3 worldPos) {
  vec4 h = uPsmCamera[i] * vec4(worldPos, 1.0);
  vec3 q = h.xyz / h.w;  // a visible point: in front of the camera, w > 0
  int layers[6];
  for (int f = 0; f < 6; ++f) layers[f] = uPsmLayerOfFace[i * 6 + f];
  return cubeFaceLayer(q, uPsmPostLight[i], layers);
}
#endif

float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  vec3 dPdx = dFdx(worldPos), dPdy = dFdy(worldPos);  // the receiver plane's, before any branch
  if (light >= PSM_LIGHTS || uPsmLayers[light] == 0) return 1.0;
  int layer = 0;
  bool face = false;
#ifdef PSM_FACES
  face = uPsmFaces[light];
  if (face) layer = faceLayer(light, worldPos);
  if (layer < 0) return 1.0;
#endif
  return projectiveLookup(light, layer, worldPos, N, dPdx, dPdy, face, texelCoords);
}

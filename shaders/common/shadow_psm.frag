#version 410 core
// The visibility of the techniques that warp space before rendering depth: perspective shadow maps
// (common/technique/psm: the original and the fixes of Kozlov et al., "Perspective Shadow Maps:
// Care and Feeding") and LiSPSM (common/technique/lispsm), linked into every lit program that
// serves them (shaders/common/scene.frag declares the function). Per light, up to six maps in one
// array texture: one map, or one per hidden face of the camera's unit cube (fix 3, PSM_FACES).
// Each map's matrix takes the world point to the map's clip space in one projective step, the
// camera's projection included.
#include "common/projective_maps.glsl"

#ifdef PSM_FACES
uniform bool uPsmFaces[PSM_LIGHTS];
uniform mat4 uPsmCamera[PSM_LIGHTS];            // the camera whose unit cube the faces are (maybe slid)
uniform vec4 uPsmPostLight[PSM_LIGHTS];         // the light there: (position, 1) or (direction, 0)
uniform int uPsmLayerOfFace[PSM_LIGHTS * 6];    // faces 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; -1: none

// The hidden face the ray from the light through the point leaves the cube by (for a direction:
// the ray through the point along -direction): algorithms/psm/cube_faces.cpp, cubeFaceOf.
int faceLayer(int i, vec3 worldPos) {
  vec4 h = uPsmCamera[i] * vec4(worldPos, 1.0);
  vec3 q = h.xyz / h.w;  // a visible point: in front of the camera, w > 0
  vec4 L = uPsmPostLight[i];
  vec3 v = L.w == 0.0 ? -L.xyz : q - L.xyz;
  vec3 o = L.w == 0.0 ? q : L.xyz;
  float best = 3.0e38;
  int layer = -1;
  for (int f = 0; f < 6; ++f) {
    int k = uPsmLayerOfFace[i * 6 + f];
    vec3 n = vec3(0.0);
    n[f / 2] = (f % 2 == 0) ? 1.0 : -1.0;
    float nv = dot(n, v);
    if (k < 0 || nv <= 0.0) continue;
    float t = (1.0 - dot(n, o)) / nv;
    if (t < best) {
      best = t;
      layer = k;
    }
  }
  return layer;
}
#endif

float shadowVisibility(int light, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (light >= PSM_LIGHTS || uPsmLayers[light] == 0) return 1.0;
  int layer = 0;
#ifdef PSM_FACES
  if (uPsmFaces[light]) layer = faceLayer(light, worldPos);
  if (layer < 0) return 1.0;
#endif
  return projectiveLookup(light, layer, worldPos, N, texelCoords);
}

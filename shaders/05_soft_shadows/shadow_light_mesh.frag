#version 410 core
// The light-mesh method of the lecture (lessons/05_soft_shadows/light_mesh; lesson 05): the light's
// visibility V(L, x_k) baked at the nodes of a regular 3D grid over the scene; a shaded point
// averages its nearest nodes, here the 8 around it with trilinear weights (a 3D texture's linear
// filter: soft::lightMeshVisibility). The lookup moves uOffset cells along the normal first, so
// the nodes inside the receiver (dark) weigh less. Times the share of the sphere above the
// receiver's horizon (soft_maps.glsl: the light's centre and radius come from there).
#include "05_soft_shadows/soft_maps.glsl"

uniform int uMeshOn[MAX_LIGHTS];
uniform sampler3D uMesh[MAX_LIGHTS];
// GLSL ES 3.00 (WebGL2) indexes an array of samplers with constants only: a switch there.
float meshAt(int i, vec3 uvw) {
#ifdef SHADOWLAB_GLES
  switch (i) {
    case 0: return texture(uMesh[0], uvw).r;
    case 1: return texture(uMesh[1], uvw).r;
    case 2: return texture(uMesh[2], uvw).r;
    default: return texture(uMesh[3], uvw).r;
  }
#else
  return texture(uMesh[i], uvw).r;
#endif
}
uniform vec3 uMeshOrigin[MAX_LIGHTS];
uniform vec3 uMeshStep[MAX_LIGHTS];
uniform vec3 uMeshNodes[MAX_LIGHTS];
uniform float uMeshOffset;  // cells along N

float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  if (uMeshOn[i] == 0) return 1.0;
  vec3 q = worldPos + N * (uMeshOffset * uMeshStep[i].y);
  // Node k sits at the centre of texel k: (k + 0.5) / nodes.
  vec3 uvw = ((q - uMeshOrigin[i]) / uMeshStep[i] + 0.5) / uMeshNodes[i];
  return meshAt(i, uvw) * softHorizon(i, worldPos, N);
}

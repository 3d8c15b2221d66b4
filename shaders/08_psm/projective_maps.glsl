// The maps of lessons/08_psm/projective_maps as the lit shader reads them (the perspective
// shadow maps and LiSPSM, shaders/08_psm/shadow_psm.frag; the cascades, shadow_cascades.frag): per
// light up to six maps, the layers of one array texture, each with the matrix that takes a world
// point to its clip space in one projective step, and the lookup with the receiver's normal offset.
#include "common/light.glsl"

const int PSM_LIGHTS = 2;  // kPsmLights in lessons/08_psm/projective_maps.hpp
const int PSM_MAPS = 6;

uniform int uPsmLayers[PSM_LIGHTS];  // 0: no map this frame (light off, nothing in view): lit
uniform mat4 uPsmMatrix[PSM_LIGHTS * PSM_MAPS];
uniform float uPsmSize[PSM_LIGHTS];  // texels per side of each map
uniform sampler2DArrayShadow uPsmMaps[PSM_LIGHTS];
uniform float uPsmConstantBias;  // window-depth units (the constant bias); 0 with the world bias
// The receiver's side, against acne on surfaces at grazing light (a + b L_texel moves casters along
// the light, which a grazing slope needs many texels of): the lookup point moves along N by
// uPsmNormalOffset texels of the map's world size THERE, times sin(theta), as lesson 03's normal
// offset does with a uniform map's one texel size. The texel size as in depth_psm.vert. Compiled in
// with PSM_NORMAL_OFFSET (bias.normal_offset > 0, or bias.plane_normal_offset > 0 with the plane).
uniform vec4 uPsmTexelStep[PSM_LIGHTS * PSM_MAPS];
uniform vec4 uPsmClipW[PSM_LIGHTS * PSM_MAPS];
uniform float uPsmNormalOffset;
uniform float uPsmPlaneNormalOffset;  // the same where the receiver plane applies (PSM_RECEIVER_PLANE)
uniform float uPsmOffsetMax;          // the most the lookup moves, world units (bias.max)
uniform Light uLights[MAX_LIGHTS];

// A point's place in a map, psmMapCoords: exercise 08.3 (GLSL). The student's with impl=student in
// lesson 08 (the maps' shaderDefines() add SHADOWLAB_STUDENT_PSM_LOOKUP), else the reference
// (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_PSM_LOOKUP
#include "08_psm/exercises.glsl"
#else
#include "08_psm/exercises_reference.glsl"
#endif

// The comparison of map `layer` at uv with depth z: 1 lit, 0 shadowed (hardware 2x2 PCF between).
float psmCompare(int light, int layer, vec2 uv, float z) {
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: outside the map is lit, as the sampler's border says natively
  if (uv != clamp(uv, 0.0, 1.0)) return 1.0;
#endif
#ifdef SHADOWLAB_GLES  // GLSL ES 3.00 (WebGL2) indexes an array of samplers with constants only
  return light == 0 ? texture(uPsmMaps[0], vec4(uv, float(layer), z)) : texture(uPsmMaps[1], vec4(uv, float(layer), z));
#else
  return texture(uPsmMaps[light], vec4(uv, float(layer), z));
#endif
}

#ifdef PSM_RECEIVER_PLANE
// The receiver plane (Isidoro, "Shadow Mapping: GPU-based Tips and Techniques", GDC 2006): the
// depth change per unit of map u and v on the receiver's plane, from the world point's screen
// steps dPdx, dPdy through the map's matrix (as projectiveTexelJacobian, with depth). A projective
// map takes planes to planes, so a planar receiver's depth is exactly linear in (u, v) across the
// footprint: each tap compares against the plane's own depth at its texel, and no texel-sized
// receiver offset is needed. ok = false where the plane is edge-on in the map or on screen.
vec2 projectiveDepthSlope(mat4 M, vec3 worldPos, vec3 dPdx, vec3 dPdy, out bool ok) {
  vec4 h = M * vec4(worldPos, 1.0), hx = M * vec4(dPdx, 0.0), hy = M * vec4(dPdy, 0.0);
  vec3 dx = hx.xyz * h.w - h.xyz * hx.w, dy = hy.xyz * h.w - h.xyz * hy.w;  // times 2 h.w^2: cancels
  float det = dx.x * dy.y - dx.y * dy.x;
  ok = h.w > 0.0 && abs(det) > 1e-9 * max(dot(dx.xy, dx.xy), dot(dy.xy, dy.xy));
  return ok ? vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det : vec2(0.0);
}

// One nearest comparison at texel t (integer coordinates) against the plane through p.
float planeTap(int light, int layer, vec3 p, vec2 slope, vec2 t) {
  vec2 uv = (t + 0.5) / uPsmSize[light];
  return psmCompare(light, layer, uv, p.z + dot(slope, uv - p.xy) - uPsmConstantBias);
}

// The 2x2 taps of hardware PCF (PSM_RECEIVER_PLANE 2), or the one nearest tap, against the plane.
float planeLookup(int light, int layer, vec3 p, vec2 slope) {
  vec2 s = p.xy * uPsmSize[light];
#if PSM_RECEIVER_PLANE == 2
  vec2 t = floor(s - 0.5), f = s - 0.5 - t;
  float a = planeTap(light, layer, p, slope, t), b = planeTap(light, layer, p, slope, t + vec2(1, 0));
  float c = planeTap(light, layer, p, slope, t + vec2(0, 1)), d = planeTap(light, layer, p, slope, t + vec2(1, 1));
  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
#else
  return planeTap(light, layer, p, slope, floor(s));
#endif
}
#endif

// The world size of one texel of map `map` at the point (as in depth_psm.vert) for the normal offset.
float projectiveTexelSize(int map, vec3 worldPos) {
  vec4 d = uPsmTexelStep[map] * dot(uPsmClipW[map], vec4(worldPos, 1.0));
  float w = 1.0 + d.w;
  return w > 0.0 ? length((worldPos + d.xyz) / w - worldPos) : 0.0;
}

// V of light `light` from its map `layer` at the surface point; texelCoords: the point's texel
// coordinates in that map (vec2(0) outside it). dPdx, dPdy: the point's screen-space steps (dFdx,
// dFdy of the world position, taken by the caller in uniform control flow) for the receiver plane.
// face: the map is the cube face chosen for the surface point (fix 3). The normal offset can carry
// the lookup across the face's edge, off its map, where the border says lit: bright seam lines
// along the cube's edges where four or five faces meet (issue 39). The lookup then stays on the
// face's edge texel, the depth beside the point.
float projectiveLookup(int light, int layer, vec3 worldPos, vec3 N, vec3 dPdx, vec3 dPdy, bool face,
                       out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  int map = light * PSM_MAPS + layer;
  vec3 L = uLights[light].kind == LIGHT_DIRECTIONAL ? -uLights[light].direction : normalize(uLights[light].position - worldPos);
  float offset = uPsmNormalOffset;
#ifdef PSM_RECEIVER_PLANE
  // The plane where the pixel's own facet faces the light, with uPsmPlaneNormalOffset. Where the
  // facet faces away but the shading normal N still faces the light (the terminator of a smooth
  // surface) the map holds the facets in front of it: one plain comparison, no offset (an offset
  // of a texel lifts thin grazing shadows off their receivers). Where N faces away too, V is not
  // seen (no diffuse light): the lookup as without the plane, uPsmNormalOffset along N.
  bool ok;
  vec2 slope = projectiveDepthSlope(uPsmMatrix[map], worldPos, dPdx, dPdy, ok);
  vec3 Ng = cross(dPdx, dPdy);
  bool plane = ok && dot(Ng, L) * dot(Ng, N) > 0.0;
  if (!plane) slope = vec2(0.0);
  offset = plane ? uPsmPlaneNormalOffset : dot(N, L) > 0.0 ? 0.0 : uPsmNormalOffset;
#endif
  vec3 q = worldPos;
#ifdef PSM_NORMAL_OFFSET
  float c = clamp(dot(N, L), 0.0, 1.0);
  q += N * min(offset * projectiveTexelSize(map, worldPos) * sqrt(1.0 - c * c), uPsmOffsetMax);
#endif
  vec4 m = psmMapCoords(uPsmMatrix[map], q);  // (u, v, depth, 1), or vec4(0.0)
  if (m.w == 0.0) return 1.0;                 // outside every light frustum: nothing known, lit
  vec3 p = m.xyz;
  texelCoords = p.xy * uPsmSize[light];  // where the point is: the measurement's Jacobian, unclamped
  if (face) p.xy = clamp(p.xy, vec2(0.5 / uPsmSize[light]), vec2(1.0 - 0.5 / uPsmSize[light]));
  if (p.z > 1.0) return 1.0;
#ifdef PSM_RECEIVER_PLANE
  return planeLookup(light, layer, p, slope);
#else
  return psmCompare(light, layer, p.xy, p.z - uPsmConstantBias);
#endif
}

// The Jacobian of map `layer`'s texel coordinates per screen pixel at a surface point, from the
// point's screen-space steps dPdx, dPdy (dFdx, dFdy of the world position): the derivative of the
// one map's projection at the point, (dh.xy h.w - h.xy dh.w) / h.w^2 with h = M p and dh = M dp,
// in texels. dFdx of texelCoords is its finite difference when the 2x2 quad reads a single map.
// vec4(0.0) (the measurement's "no map") at or behind the map's projection centre (h.w ~ 0 or less:
// no place in the map, and a derivative through 1 / h.w that explodes).
vec4 projectiveTexelJacobian(int light, int layer, vec3 worldPos, vec3 dPdx, vec3 dPdy) {
  mat4 M = uPsmMatrix[light * PSM_MAPS + layer];
  vec4 h = M * vec4(worldPos, 1.0), hx = M * vec4(dPdx, 0.0), hy = M * vec4(dPdy, 0.0);
  if (h.w < 1e-6) return vec4(0.0);
  vec2 jx = (hx.xy * h.w - h.xy * hx.w) / (h.w * h.w), jy = (hy.xy * h.w - h.xy * hy.w) / (h.w * h.w);
  return vec4(jx, jy) * (0.5 * uPsmSize[light]);  // clip xy in [-1, 1] -> uv in [0, 1] -> texels
}

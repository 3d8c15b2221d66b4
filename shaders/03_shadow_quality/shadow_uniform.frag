#version 410 core
// The uniform shadow-map technique's visibility (lessons/03_shadow_quality/uniform_maps; lesson 03), linked
// into every lit program that serves it (shaders/common/scene.frag declares the function). Per
// light, one of three maps: a fitted orthographic 2D map (directional), a perspective 2D map (spot)
// or a cube map (point); the bias family and the PCF family on top. Mirrors
// common/algorithms/shadow_math; keep the two in step.
//
// Specialised by the technique's shaderDefines(): SHADOW_TYPES t0, t1, t2, t3 (each light's map),
// SHADOW_FILTER f, PCF_SIZE n, RECEIVER_PLANE 0|1, so a software renderer runs only the lookup each
// light needs; without them the same code reads the uniforms (the generic variant).
#include "common/light.glsl"
#include "common/shadow_bias.glsl"
// softTapTurn, the Poisson taps' per-pixel turn (exercise 05.4's rotation: sealed in the handout).
#include "common/soft_answers.glsl"

const int SHADOW_NONE = 0, SHADOW_ORTHO = 1, SHADOW_PERSPECTIVE = 2, SHADOW_CUBE = 3;

uniform Light uLights[MAX_LIGHTS];
uniform int uShadowType[MAX_LIGHTS];           // SHADOW_NONE: no map (the light is off): lit
uniform mat4 uShadowMatrix[MAX_LIGHTS];        // 2D maps: the texture matrix ([Boreskov2005])
uniform float uShadowTexel[MAX_LIGHTS];        // ortho: world size of a texel; perspective: 2 tan(fov/2) / size
uniform float uShadowSize[MAX_LIGHTS];         // texels per side (of a cube face)
// One sampler per light and kind, picked by a switch on the light's index: a sampler array
// indexed by a variable makes a software renderer consider every sampler at every tap.
uniform sampler2DShadow uShadowMap0, uShadowMap1, uShadowMap2, uShadowMap3;
uniform samplerCubeShadow uShadowCube0, uShadowCube1, uShadowCube2, uShadowCube3;
uniform float uCubeNear, uCubeFar;

uniform int uFilter;           // 0 nearest, 1 hardware 2x2, 2 N x N, 3 Poisson disk (rotated)
uniform int uPcfSize;          // N (odd)
uniform float uPoissonRadius;  // in texels
uniform bool uReceiverPlane;   // receiver-plane depth bias for the filter taps

#ifdef SHADOW_TYPES
const int kShadowType[MAX_LIGHTS] = int[](SHADOW_TYPES);
#define SHADOW_TYPE(i) kShadowType[i]
#define FILTER SHADOW_FILTER
#define PCF_N PCF_SIZE
#define USE_RECEIVER_PLANE (RECEIVER_PLANE != 0)
#else
#define SHADOW_TYPE(i) uShadowType[i]
#define FILTER uFilter
#define PCF_N uPcfSize
#define USE_RECEIVER_PLANE uReceiverPlane
#endif

const vec2 POISSON[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.094184101, -0.92938870), vec2(0.34495938, 0.29387760),
    vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464), vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379),
    vec2(0.44323325, -0.97511554), vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367), vec2(0.14383161, -0.14100790));

float tap2D(int i, vec3 p) {
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: outside the map is lit, as the sampler's border says natively
  if (p.xy != clamp(p.xy, 0.0, 1.0)) return 1.0;
#endif
  switch (i) {
    case 0: return textureLod(uShadowMap0, p, 0.0);
    case 1: return textureLod(uShadowMap1, p, 0.0);
    case 2: return textureLod(uShadowMap2, p, 0.0);
    default: return textureLod(uShadowMap3, p, 0.0);
  }
}

float tapCube(int i, vec4 p) {
  switch (i) {
    case 0: return textureGrad(uShadowCube0, p, vec3(0.0), vec3(0.0));
    case 1: return textureGrad(uShadowCube1, p, vec3(0.0), vec3(0.0));
    case 2: return textureGrad(uShadowCube2, p, vec3(0.0), vec3(0.0));
    default: return textureGrad(uShadowCube3, p, vec3(0.0), vec3(0.0));
  }
}

// The N x N kernel, pcfKernel: exercise 03.6 (GLSL). The student's with impl=student in lesson 03
// (the technique's shaderDefines() add SHADOWLAB_STUDENT_PCF), else the reference (sealed in the
// student handout).
#ifdef SHADOWLAB_STUDENT_PCF
#include "03_shadow_quality/exercises.glsl"
#else
#include "03_shadow_quality/exercises_reference.glsl"
#endif

float rotationAngle(vec2 pixel) {  // shadow::rotationAngle
  return fract(sin(dot(pixel, vec2(12.9898, 78.233))) * 43758.5453) * 6.28318530718;
}

// A filtered lookup in a 2D map. p = (u, v, depth); dzduv: the receiver plane's depth slope in
// texture space (0 when off), so each tap compares against the plane's depth at the tap.
float filtered2D(int map, vec3 p, float bias, vec2 dzduv, float size) {
  if (p.z > 1.0) return 1.0;
  float ref = p.z - bias;
  if (FILTER <= 1) return tap2D(map, vec3(p.xy, ref));  // the sampler is nearest or linear
  float texel = 1.0 / size, sum = 0.0;
  if (FILTER == 2) return pcfKernel(map, p.xy, ref, dzduv, texel, PCF_N);
  float a = rotationAngle(gl_FragCoord.xy);
  mat2 R = softTapTurn(a);
  for (int i = 0; i < 16; ++i) {
    vec2 o = R * POISSON[i] * uPoissonRadius * texel;
    sum += tap2D(map, vec3(p.xy + o, ref + dot(dzduv, o)));
  }
  return sum / 16.0;
}

// The receiver plane (Isidoro 2006): from the screen derivatives of (u, v, depth), the depth
// change per unit of u and v.
vec2 receiverPlane(vec3 p) {
  vec3 dx = dFdx(p), dy = dFdy(p);
  float det = dx.x * dy.y - dx.y * dy.x;
  if (!USE_RECEIVER_PLANE || abs(det) < 1e-12) return vec2(0.0);
  return vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
}

float cubeDepth(float majorAxis) {  // shadow::cubeDepth
  float ndc = (uCubeFar + uCubeNear) / (uCubeFar - uCubeNear) - 2.0 * uCubeFar * uCubeNear / ((uCubeFar - uCubeNear) * majorAxis);
  return 0.5 * ndc + 0.5;
}

float cubeVisibility(int map, vec3 lightPos, vec3 q, float cosTheta, float size) {
  vec3 d = q - lightPos;
  vec3 a = abs(d);
  float major = max(a.x, max(a.y, a.z));
  if (major >= uCubeFar) return 1.0;
  // Bias in window depth: the slope-scaled bias times the depth's rate at this distance.
  float ref = cubeDepth(major) - slopeScaledBias(cosTheta) * (uCubeNear / major);
  if (FILTER <= 1) return tapCube(map, vec4(d, ref));
  // Taps on the plane across the lookup direction, one texel = 2 major / size.
  vec3 n = normalize(d);
  vec3 t = normalize(cross(n, abs(n.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
  vec3 b = cross(n, t);
  float texel = 2.0 * major / size, sum = 0.0;
  float angle = rotationAngle(gl_FragCoord.xy);
  int count = FILTER == 2 ? PCF_N * PCF_N : 16;
  for (int i = 0; i < count; ++i) {
    vec2 o = FILTER == 2 ? vec2(i % PCF_N - PCF_N / 2, i / PCF_N - PCF_N / 2)
                          : mat2(cos(angle), sin(angle), -sin(angle), cos(angle)) * POISSON[i] * uPoissonRadius;
    sum += tapCube(map, vec4(d + (t * o.x + b * o.y) * texel, ref));
  }
  return sum / float(count);
}

// V of light i at the surface point. Call in uniform control flow (before any discard): the
// receiver plane and the aliasing measurement take screen-space derivatives. Normal offset: the
// lookup point moves along the normal by a few texels' world size, scaled by sin(theta) (nothing
// head-on, most at grazing light).
float shadowVisibility(int i, vec3 worldPos, vec3 N, out vec2 texelCoords) {
  texelCoords = vec2(0.0);
  int type = SHADOW_TYPE(i);
  if (type == SHADOW_NONE) return 1.0;
  vec3 toLightPos = uLights[i].position - worldPos;
  if (type == SHADOW_CUBE) {
    float cosPoint = dot(N, normalize(toLightPos));
    vec3 q = worldPos + N * uNormalOffset * 2.0 * length(toLightPos) / uShadowSize[i] *
                            sqrt(max(1.0 - cosPoint * cosPoint, 0.0));
    return cubeVisibility(i, uLights[i].position, q, cosPoint, uShadowSize[i]);
  }
  float cosTheta;
  vec3 q = normalOffsetPoint(uLights[i], type == SHADOW_PERSPECTIVE, uShadowTexel[i], worldPos, N, cosTheta);
  vec4 h = uShadowMatrix[i] * vec4(q, 1.0);
  vec3 p = h.w > 0.0 ? h.xyz / h.w : vec3(0.5, 0.5, 2.0);  // behind a spot: nothing known, lit
  vec2 plane = receiverPlane(p);
  texelCoords = p.xy * uShadowSize[i];
  return filtered2D(i, p, slopeScaledBias(cosTheta), plane, uShadowSize[i]);
}

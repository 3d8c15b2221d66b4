#version 410 core
// Lesson 03: three lights, each with its map (sun: fitted orthographic 2D map, point: cube map,
// spot: perspective 2D map), the bias family and the PCF family. Mirrors common/algorithms/shadow_math.
#include "common/lighting.glsl"
#include "common/measure.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

const int SUN = 0, POINT = 1, SPOT = 2;
uniform Light uLights[3];
uniform sampler2DShadow uSunMap;
uniform sampler2DShadow uSpotMap;
uniform samplerCubeShadow uPointMap;
uniform mat4 uSunMatrix, uSpotMatrix;    // texture matrices (seeds 002)
uniform float uSunTexelWorld;            // world size of one sun texel (the fit gives it)
uniform float uSpotTexelAngle;           // 2 tan(fov/2) / size: a spot texel is this times distance
uniform float uPointNear, uPointFar;
uniform float uMapSize, uCubeSize;

uniform int uFilter;          // 0 nearest, 1 hardware 2x2, 2 N x N, 3 Poisson disk (rotated)
uniform int uPcfSize;         // N (odd)
uniform float uPoissonRadius; // in texels
uniform float uConstantBias;  // depth units
uniform float uSlopeBias;     // depth units per unit of tan(theta)
uniform float uMaxBias;
uniform float uNormalOffset;  // texels of world offset along the normal
uniform bool uReceiverPlane;  // receiver-plane depth bias for the filter taps

uniform vec3 uEye;
uniform vec3 uAmbient;
uniform vec3 uAlbedo;
uniform float uSpecular, uShininess;
uniform bool uUseTexture;
uniform sampler2D uTexture;
uniform float uAlphaCutoff;
uniform bool uTwoSided;
uniform int uView;            // 0 lit, 1 visibility of the measured light (or the sun)

out vec4 fragColor;

const vec2 POISSON[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.094184101, -0.92938870), vec2(0.34495938, 0.29387760),
    vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464), vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379),
    vec2(0.44323325, -0.97511554), vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367), vec2(0.14383161, -0.14100790));

float slopeScaledBias(float cosTheta) {  // shadow::slopeScaledBias
  if (cosTheta <= 0.0) return uMaxBias;
  float c = min(cosTheta, 1.0);
  return min(uConstantBias + uSlopeBias * sqrt(1.0 - c * c) / c, uMaxBias);
}

float rotationAngle(vec2 pixel) {         // shadow::rotationAngle
  return fract(sin(dot(pixel, vec2(12.9898, 78.233))) * 43758.5453) * 6.28318530718;
}

// A filtered lookup in a 2D map. p = (u, v, depth); dzduv: the receiver plane's depth slope in
// texture space (0 when off), so each tap compares against the plane's depth at the tap.
float filtered2D(sampler2DShadow map, vec3 p, float bias, vec2 dzduv, float size) {
  if (p.z > 1.0) return 1.0;
  float ref = p.z - bias;
  if (uFilter <= 1) return texture(map, vec3(p.xy, ref));  // the sampler is nearest or linear
  float texel = 1.0 / size, sum = 0.0;
  if (uFilter == 2) {
    int h = uPcfSize / 2;
    for (int y = -h; y <= h; ++y)
      for (int x = -h; x <= h; ++x) {
        vec2 o = vec2(x, y) * texel;
        sum += texture(map, vec3(p.xy + o, ref + dot(dzduv, o)));
      }
    return sum / float(uPcfSize * uPcfSize);
  }
  float a = rotationAngle(gl_FragCoord.xy);
  mat2 R = mat2(cos(a), sin(a), -sin(a), cos(a));
  for (int i = 0; i < 16; ++i) {
    vec2 o = R * POISSON[i] * uPoissonRadius * texel;
    sum += texture(map, vec3(p.xy + o, ref + dot(dzduv, o)));
  }
  return sum / 16.0;
}

// The receiver plane (Isidoro 2006): from the screen derivatives of (u, v, depth), the depth
// change per unit of u and v.
vec2 receiverPlane(vec3 p) {
  vec3 dx = dFdx(p), dy = dFdy(p);
  float det = dx.x * dy.y - dx.y * dy.x;
  if (!uReceiverPlane || abs(det) < 1e-12) return vec2(0.0);
  return vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
}

float cubeDepth(float majorAxis) {        // shadow::cubeDepth
  float ndc = (uPointFar + uPointNear) / (uPointFar - uPointNear) - 2.0 * uPointFar * uPointNear / ((uPointFar - uPointNear) * majorAxis);
  return 0.5 * ndc + 0.5;
}

float pointVisibility(vec3 q, float cosTheta) {
  vec3 d = q - uLights[POINT].position;
  vec3 a = abs(d);
  float major = max(a.x, max(a.y, a.z));
  if (major >= uPointFar) return 1.0;
  // Bias in window depth: the slope-scaled bias times the depth's rate at this distance.
  float ref = cubeDepth(major) - slopeScaledBias(cosTheta) * (uPointNear / major);
  if (uFilter <= 1) return texture(uPointMap, vec4(d, ref));
  // Taps on the plane across the lookup direction, one texel = 2 major / size.
  vec3 n = normalize(d);
  vec3 t = normalize(cross(n, abs(n.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
  vec3 b = cross(n, t);
  float texel = 2.0 * major / uCubeSize, sum = 0.0;
  float angle = rotationAngle(gl_FragCoord.xy);
  int count = uFilter == 2 ? uPcfSize * uPcfSize : 16;
  for (int i = 0; i < count; ++i) {
    vec2 o = uFilter == 2 ? vec2(i % uPcfSize - uPcfSize / 2, i / uPcfSize - uPcfSize / 2)
                          : mat2(cos(angle), sin(angle), -sin(angle), cos(angle)) * POISSON[i] * uPoissonRadius;
    sum += texture(uPointMap, vec4(d + (t * o.x + b * o.y) * texel, ref));
  }
  return sum / float(count);
}

void main() {
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (uTwoSided && dot(N, V) < 0.0) N = -N;
  // Shadow coordinates first, in uniform control flow (their derivatives drive the receiver plane
  // and the aliasing measurement). Normal offset: look up from a point moved along the normal by a
  // few texels' world size, scaled by sin(theta) (nothing head-on, most at grazing light).
  float cosSun = dot(N, -uLights[SUN].direction);
  vec3 sunQ = vWorldPos + N * uNormalOffset * uSunTexelWorld * sqrt(max(1.0 - cosSun * cosSun, 0.0));
  vec4 sunH = uSunMatrix * vec4(sunQ, 1.0);
  vec3 sunP = sunH.xyz / sunH.w;
  vec2 sunPlane = receiverPlane(sunP);
  vec3 toSpot = uLights[SPOT].position - vWorldPos;
  float cosSpot = dot(N, normalize(toSpot));
  vec3 spotQ = vWorldPos + N * uNormalOffset * uSpotTexelAngle * length(toSpot) * sqrt(max(1.0 - cosSpot * cosSpot, 0.0));
  vec4 spotH = uSpotMatrix * vec4(spotQ, 1.0);
  vec3 spotP = spotH.w > 0.0 ? spotH.xyz / spotH.w : vec3(0.5, 0.5, 2.0);
  vec2 spotPlane = receiverPlane(spotP);

  vec4 texel = uUseTexture ? texture(uTexture, vUv) : vec4(1.0);
  if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;

  float vis[3];
  vis[SUN] = uLights[SUN].enabled ? filtered2D(uSunMap, sunP, slopeScaledBias(cosSun), sunPlane, uMapSize) : 1.0;
  vis[SPOT] = uLights[SPOT].enabled ? filtered2D(uSpotMap, spotP, slopeScaledBias(cosSpot), spotPlane, uMapSize) : 1.0;
  vec3 toPoint = uLights[POINT].position - vWorldPos;
  float cosPoint = dot(N, normalize(toPoint));
  vec3 pointQ = vWorldPos + N * uNormalOffset * 2.0 * length(toPoint) / uCubeSize * sqrt(max(1.0 - cosPoint * cosPoint, 0.0));
  vis[POINT] = uLights[POINT].enabled ? pointVisibility(pointQ, cosPoint) : 1.0;

  int m = clamp(uMeasureLight, 0, 2);
  vec2 texelCoords = m == SUN ? sunP.xy * uMapSize : m == SPOT ? spotP.xy * uMapSize : vec2(0.0);
  writeMeasurement(vWorldPos, N, vis[m], texelCoords);

  if (uView == 1) { fragColor = vec4(vec3(vis[uMeasureLight >= 0 ? m : SUN]), 1.0); return; }
  vec3 kd = uAlbedo * texel.rgb;
  vec3 color = uAmbient * kd;
  for (int i = 0; i < 3; ++i)
    color += lightContribution(N, toLight(uLights[i], vWorldPos), V, incidentRadiance(uLights[i], vWorldPos), vis[i], kd,
                               uSpecular, uShininess, true);
  fragColor = vec4(toDisplay(color), 1.0);
}

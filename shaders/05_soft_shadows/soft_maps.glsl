// The soft-shadow techniques' shared half (lessons/05_soft_shadows/soft_maps; lesson 05): per light a
// perspective camera at the centre of its spherical emitter, the sample points on the sphere and
// one depth map per sample in an array texture. Mirrors common/algorithms/soft_shadows.
//   view space: the centre camera looks down -z; z = -view.z is the distance along its axis
//   uv = 0.5 + view.xy / (2 z tan(fov/2)); sample k's camera sits at R s_k in that view space
//   a cube (a point light inside the scene, uSoftFaces = 6): the view space of the face the
//   point's major axis picks (softLightView), each face a frustum of its own, wider than 90 degrees
#include "common/light.glsl"

#ifndef SOFT_MAX_SAMPLES
#define SOFT_MAX_SAMPLES 64
#endif

// A tap loop that whole groups of pixels skip (PCSS's filter, where the search found no blocker)
// runs to a count held in a uniform, over an array of SOFT_MAX_TAPS, so that the compiler cannot
// unroll it (docs/performance.md, "Work few pixels need: in a loop's second trip").
#ifndef SOFT_MAX_TAPS
#define SOFT_MAX_TAPS 64
#endif

uniform Light uLights[MAX_LIGHTS];
uniform int uSoftLayer[MAX_LIGHTS];        // light i's first layer; -1: no soft shadow (lit)
uniform int uSoftFaces[MAX_LIGHTS];        // 1: one frustum; 6: a cube of faces
uniform mat4 uSoftView[MAX_LIGHTS];        // the centre camera's view (a cube's: not turned)
uniform mat3 uSoftFaceTurn[6];             // a cube face's turn of that view (shadow::cubeFaceView)
uniform float uSoftRadius[MAX_LIGHTS];     // R
uniform float uSoftTanHalfFov[MAX_LIGHTS];
uniform vec2 uSoftDepthRange[MAX_LIGHTS];  // near, far
uniform float uSoftCasterNear[MAX_LIGHTS]; // the nearest caster along the axis (>= near)
uniform vec3 uSoftSamples[SOFT_MAX_SAMPLES];  // unit-ball points in the light's view space
uniform int uSoftSampleCount;
uniform float uSoftMapSize;
uniform float uSoftBias, uSoftSlopeBias;  // texels of world size at the receiver; per tan(theta)
uniform float uSoftNormalOffset;          // texels along the normal
uniform float uSoftCardSlopeBias, uSoftCardNormalOffset;  // the same two on two-sided materials
#include "common/two_sided.glsl"        // scene.frag's: the receiver is a two-sided card
uniform sampler2DArrayShadow uSoftMaps;   // comparison, GL_LINEAR: hardware 2x2 PCF per lookup
uniform sampler2DArray uSoftDepths;       // the same texture, raw: the blocker search reads depths

// The cube face whose maps the lookups read: the one the last softLightView chose (0 for one
// frustum). A shadowVisibility call looks up around one receiver, on its face; the face's frustum
// is wide enough (soft_maps.hpp, kCubeTanHalfFov) that its kernels and samples stay on it.
int softFace = 0;

// worldPos in the view space of light i's frustum that sees it: the centre camera's, or a cube's
// face along the point's major axis (kept in softFace for the lookups that follow).
vec3 softLightView(int i, vec3 worldPos) {
  vec3 v = (uSoftView[i] * vec4(worldPos, 1.0)).xyz;
  softFace = 0;
  if (uSoftFaces[i] != 6) return v;
  vec3 a = abs(v);
  softFace = a.x >= a.y && a.x >= a.z ? (v.x >= 0.0 ? 0 : 1) : a.y >= a.z ? (v.y >= 0.0 ? 2 : 3) : (v.z >= 0.0 ? 4 : 5);
  return uSoftFaceTurn[softFace] * v;
}
// A direction (a normal) in that view space; and a point of it back in the centre camera's.
vec3 softLightViewDirection(int i, vec3 d) {
  vec3 v = mat3(uSoftView[i]) * d;
  return uSoftFaces[i] == 6 ? uSoftFaceTurn[softFace] * v : v;
}
vec3 softUnturn(int i, vec3 view) { return uSoftFaces[i] == 6 ? transpose(uSoftFaceTurn[softFace]) * view : view; }
// The layer of sample k's map on the current face.
float softLayer(int i, int k) { return float(uSoftLayer[i] + softFace * uSoftSampleCount + k); }

// Window depth of view distance z in light i's perspective maps (glm::perspective, GL depth [0,1]).
float softWindowDepth(int i, float z) {
  vec2 r = uSoftDepthRange[i];
  return clamp(r.y / (r.y - r.x) * (1.0 - r.x / z), 0.0, 1.0);
}
float softLinearDepth(int i, float d) {
  vec2 r = uSoftDepthRange[i];
  return r.x * r.y / (r.y - d * (r.y - r.x));
}

// A receiver seen from light i's centre camera, moved along N by the normal offset first.
struct SoftReceiver {
  vec3 view;       // view-space position (after the normal offset)
  vec2 uv;
  float z;         // distance along the axis
  float texel;     // world size of one map texel at the receiver
  float tanTheta;  // of the angle between N and the direction to the light, capped at 10
  float slopeBias; // uSoftSlopeBias, or uSoftCardSlopeBias on a two-sided card
  bool seam;       // a cube's pixel quad spans two faces: its screen derivatives of uv mean nothing
  vec3 normal;     // N in the same view space
};

SoftReceiver softReceiver(int i, vec3 worldPos, vec3 N) {
  SoftReceiver r;
  float cosT = clamp(dot(N, normalize(uLights[i].position - worldPos)), 1e-3, 1.0);
  float sinT = sqrt(max(1.0 - cosT * cosT, 0.0));
  float distance = max(-softLightView(i, worldPos).z, 1e-3);
  r.texel = 2.0 * distance * uSoftTanHalfFov[i] / uSoftMapSize;
  r.tanTheta = min(sinT / cosT, 10.0);
  r.slopeBias = uTwoSided ? uSoftCardSlopeBias : uSoftSlopeBias;
  float offset = uTwoSided ? uSoftCardNormalOffset : uSoftNormalOffset;
  r.view = softLightView(i, worldPos + N * (offset * r.texel * sinT));
  r.z = max(-r.view.z, 1e-4);
  r.uv = 0.5 + r.view.xy / (2.0 * r.z * uSoftTanHalfFov[i]);
  r.normal = softLightViewDirection(i, N);
  r.seam = fwidth(float(softFace)) > 0.0;  // called in uniform control flow, as derivatives need
  return r;
}

float softBias(SoftReceiver r) { return (uSoftBias + r.slopeBias * r.tanTheta) * r.texel; }

// Nothing is known in front of the near plane (behind the light) or beyond the far plane: lit.
bool softOutside(int i, SoftReceiver r) { return r.z <= uSoftDepthRange[i].x || r.z >= uSoftDepthRange[i].y; }

// The point `view` (centre camera's view space) as sample k of light i sees it: (uv, z).
vec3 softProjectSample(int i, vec3 view, int k) {
  vec3 w = view - uSoftRadius[i] * uSoftSamples[k];
  float z = max(-w.z, 1e-4);
  return vec3(0.5 + w.xy / (2.0 * z * uSoftTanHalfFov[i]), z);
}

// Sample k's map at uv for a receiver at view distance z (bias already subtracted): 1 lit, 0
// shadowed, hardware 2x2 PCF between.
float softCompare(int i, int k, vec2 uv, float z) {
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: outside the map is lit, as the sampler's border says natively
  if (uv != clamp(uv, 0.0, 1.0)) return 1.0;
#endif
  return texture(uSoftMaps, vec4(uv, softLayer(i, k), softWindowDepth(i, z)));
}

// The stored depth of sample k's map at uv, as a view distance (far outside the map).
float softDepthAt(int i, int k, vec2 uv) {
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: the border's depth 1, as natively
  if (uv != clamp(uv, 0.0, 1.0)) return softLinearDepth(i, 1.0);
#endif
  return softLinearDepth(i, texture(uSoftDepths, vec3(uv, softLayer(i, k))).r);
}

// The lecture's A_frac of t = a / R and its linear approximation, softVisibleFraction(t) and
// softProfile(t, linear) (exercise 05.2: sealed in the student handout with 05.1's and 05.3's).
#include "common/soft_answers.glsl"

// The mean of `count` samples' comparisons: the many point lights on the sphere, each a hard
// shadow; their average is the fraction of the sphere the point sees, up to the sampling. A sample
// below the receiver's horizon (its tangent plane, normalView in the light's view space) is hidden
// by the receiver itself, whatever its map says; normalView = 0 (a grid node) has no horizon.
float softSampledVisibility(int i, vec3 view, vec3 normalView, float bias, int count) {
  float v = 0.0;
  for (int k = 0; k < count; ++k) {
    if (dot(normalView, uSoftRadius[i] * uSoftSamples[k] - view) < 0.0) continue;
    vec3 s = softProjectSample(i, view, k);
    v += softCompare(i, k, s.xy, s.z - bias);
  }
  return v / float(count);
}

// The share of the sphere above the receiver's tangent plane: the light's centre is a = N.(L - p)
// above it, so A_frac(a / R) of the disk shows (soft::visibleFraction). A map cannot know it: the
// receiver is not in front of itself. Multiplies the single-map techniques' V.
float softHorizon(int i, vec3 worldPos, vec3 N) {
  float a = dot(N, uLights[i].position - worldPos);
  return uSoftRadius[i] > 0.0 ? softVisibleFraction(a / uSoftRadius[i]) : (a > 0.0 ? 1.0 : 0.0);
}

// The per-pixel rotation of the Poisson taps (shadow::rotationAngle).
float softRotation(vec2 pixel) { return fract(sin(dot(pixel, vec2(12.9898, 78.233))) * 43758.5453) * 6.28318530718; }

// The receiver plane (Isidoro 2006) in (uv, z): the depth change per unit of u and v, from the
// screen derivatives dx, dy of (uv, z); the slope capped at tan(theta) = 10. Where a cube's pixel
// quad spans two faces the derivatives mix two faces' uv: there the plane comes from the normal
// (without one, a line of pixels along the seam shadowed itself).
vec2 softReceiverPlane(vec3 dx, vec3 dy, SoftReceiver r, int i) {
  vec2 plane;
  if (r.seam) {
    // The tangent plane n.(Q - P) = 0 in (uv, z): dz/du = -2 tan(fov/2) z^2 n.x / (n.P), as v with n.y.
    float nP = dot(r.normal, r.view);
    if (abs(nP) < 1e-8) return vec2(0.0);
    plane = -2.0 * uSoftTanHalfFov[i] * r.z * r.z * r.normal.xy / nP;
  } else {
    float det = dx.x * dy.y - dx.y * dy.x;
    if (abs(det) < 1e-14) return vec2(0.0);
    plane = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
  }
  float cap = 10.0 * 2.0 * r.z * uSoftTanHalfFov[i];
  float len = length(plane);
  return len > cap ? plane * (cap / len) : plane;
}


#version 410 core
// Lesson 06, pass 1: texture coordinates, filtering, combination with the material, normal maps.
// Outputs: 0 the colour; 1 (u, v, coverage, hardware lambda); 2 d(uv)/dx, d(uv)/dy, so the CPU
// can sample exactly the same footprints (reference view, readout under the cursor).
in vec3 vObjectPos;
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

uniform sampler2D uTex;        // the filtered texture: its sampler object holds every mode
uniform sampler2D uNormalMap;  // tangent-space normals matching the bricks
uniform sampler2D uRip;        // RIP map atlas, read with texelFetch (filtering done here)
uniform sampler3D uVolume;     // 3D texture: a slice at r = uSlice
// The modes: constants in a specialised build (the lesson defines UV_MODE, VIEW, ...; one program
// per mode set, so a software renderer pays only the chosen path), uniforms in the generic one.
#ifdef UV_MODE
#define UV_MODE_ UV_MODE
#define VIEW_ VIEW
#define SAMPLING_ SAMPLING
#define COMBINE_ COMBINE
#define CHANNELS_ CHANNELS
#define NORMAL_MAPPING_ (NORMAL_MAPPING != 0)
#else
uniform int uUvMode;           // 0 explicit, 1 planar, 2 cylindrical, 3 spherical
uniform int uView;             // 0 shaded, 1 mip level, 2 anisotropy, 3 raw texture (CPU comparisons)
uniform int uSampling;         // 0 hardware, 1 RIP map in this shader, 2 3D texture slice
uniform int uCombine;          // 0 replace, 1 modulate, 2 blend
uniform int uChannels;         // 0 rgb, 1 luminance, 2 alpha (luminance as coverage)
uniform bool uNormalMapping;
#define UV_MODE_ uUvMode
#define VIEW_ uView
#define SAMPLING_ uSampling
#define COMBINE_ uCombine
#define CHANNELS_ uChannels
#define NORMAL_MAPPING_ uNormalMapping
#endif
uniform vec2 uUvScale;         // tiling
uniform vec3 uEnvColor;        // the blend mode's constant colour C_c
uniform vec3 uMaterial;        // C_f's diffuse colour
uniform vec3 uSky;
uniform vec3 uLightPos;
uniform vec3 uEye;
uniform ivec2 uTexSize;
uniform float uLodBias;
#ifdef SHADOWLAB_NO_BORDER_CLAMP
uniform vec2 uWrapBorder;  // 1 on an axis whose wrap is clamp_to_border
uniform vec4 uBorderColor;
#endif
uniform float uMaxAniso;
uniform float uSlice;
uniform int uRipLevels[2];     // levels along x and y
uniform int uRipOffsetX[16];
uniform int uRipOffsetY[16];

layout(location = 0) out vec4 fragColor;
layout(location = 1) out vec4 fragUv;
layout(location = 2) out vec4 fragDerivs;

const float PI = 3.14159265358979;

vec2 textureCoordinates() {
  vec3 p = vObjectPos;
  if (UV_MODE_ == 1) return p.xz;                                          // plane: (x, z)
  float phi = atan(p.x, p.z);
  if (phi < 0.0) phi += 2.0 * PI;
  if (UV_MODE_ == 2) return vec2(phi / (2.0 * PI), p.y);                   // cylinder: (phi, y)
  if (UV_MODE_ == 3) return vec2(phi / (2.0 * PI), acos(clamp(p.y / max(length(p), 1e-6), -1.0, 1.0)) / PI);
  return vUv;
}

// ---- RIP map: u and v levels chosen independently, bilinear inside, linear between -------------
ivec2 ripLevelSize(ivec2 level) { return max(uTexSize >> level, ivec2(1)); }
vec4 ripTexel(ivec2 level, ivec2 t) {  // texel t of a level, wrapped (REPEAT)
  ivec2 size = ripLevelSize(level);
  t -= size * ivec2(floor(vec2(t) / vec2(size)));  // GLSL leaves % of negative numbers undefined
  return texelFetch(uRip, ivec2(uRipOffsetX[level.x], uRipOffsetY[level.y]) + t, 0);
}
// The level of detail per axis and the filter inside a level: exercises 06.8 and 06.9 (yours with
// impl=student; the reference's is withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_GLSL
#include "exercises.glsl"
#else
#include "exercises_reference.glsl"
#endif
vec4 sampleRip(vec2 uv, vec2 dx, vec2 dy) {
  ivec2 last = ivec2(uRipLevels[0] - 1, uRipLevels[1] - 1);
  vec2 lod = clamp(ripLevelOfDetail(dx, dy, uTexSize) + uLodBias, vec2(0.0), vec2(last));
  ivec2 l0 = ivec2(floor(lod));
  ivec2 l1 = min(l0 + 1, last);
  vec2 f = lod - vec2(l0);
  return mix(mix(ripBilinear(l0, uv), ripBilinear(ivec2(l1.x, l0.y), uv), f.x),
             mix(ripBilinear(ivec2(l0.x, l1.y), uv), ripBilinear(l1, uv), f.x), f.y);
}

vec3 levelColour(float level) {
  const vec3 palette[8] = vec3[8](vec3(0.2, 0.2, 1.0), vec3(0.0, 0.8, 1.0), vec3(0.0, 0.9, 0.3), vec3(0.8, 1.0, 0.0),
                                  vec3(1.0, 0.7, 0.0), vec3(1.0, 0.2, 0.0), vec3(0.9, 0.0, 0.6), vec3(1.0, 1.0, 1.0));
  float l = clamp(level, 0.0, 7.0);
  int i = int(floor(l));
  return mix(palette[i], palette[min(i + 1, 7)], l - float(i));
}

// Tangent frame from screen-space derivatives: works for every projection, no tangents stored.
mat3 cotangentFrame(vec3 N, vec3 p, vec2 uv) {
  vec3 dp1 = dFdx(p), dp2 = dFdy(p);
  vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, N), dp1perp = cross(N, dp1);
  vec3 T = dp2perp * duv1.x + dp1perp * duv2.x;
  vec3 B = dp2perp * duv1.y + dp1perp * duv2.y;
  float s = inversesqrt(max(max(dot(T, T), dot(B, B)), 1e-20));
  return mat3(T * s, B * s, N);
}

#ifdef SHADOWLAB_GLES
// GLSL ES 3.00 (WebGL2) has no textureQueryLod, nor a sampler LOD bias: the level the textbook
// computes from the derivatives stands in for the hardware's, and the bias goes to the lookup.
vec2 queryLod(vec2 uv, vec2 dx, vec2 dy) {
  vec2 size = vec2(textureSize(uTex, 0));
  float lambda = log2(max(max(length(dx * size), length(dy * size)), 1e-8)) + uLodBias;
  return vec2(clamp(lambda, 0.0, floor(log2(max(size.x, size.y)))), lambda);
}
#define TEXTURE_BIASED(s, uv) texture(s, uv, uLodBias)
#else
vec2 queryLod(vec2 uv, vec2 dx, vec2 dy) { return textureQueryLod(uTex, uv); }
#define TEXTURE_BIASED(s, uv) texture(s, uv)  // the sampler object holds the bias
#endif

void main() {
  vec2 uv = textureCoordinates() * uUvScale;
  vec2 dx = dFdx(uv), dy = dFdy(uv);
  vec2 hwLod = queryLod(uv, dx, dy);  // (level used, lambda): what the hardware computed
  fragUv = vec4(uv, 1.0, hwLod.y);
  fragDerivs = vec4(dx, dy);

  vec4 tex;
  if (SAMPLING_ == 1) tex = sampleRip(uv, dx, dy);
  else if (SAMPLING_ == 2) tex = texture(uVolume, vec3(uv, uSlice));
  else tex = TEXTURE_BIASED(uTex, uv);
#ifdef SHADOWLAB_NO_BORDER_CLAMP  // WebGL2: clamp_to_border is clamp_to_edge, and the border painted here
  bvec2 outside = bvec2(uv.x < 0.0 || uv.x > 1.0, uv.y < 0.0 || uv.y > 1.0);
  if ((outside.x && uWrapBorder.x > 0.5) || (outside.y && uWrapBorder.y > 0.5)) tex = uBorderColor;
#endif

  if (VIEW_ == 1) {  // mip level the hardware picks, over the texture's luminance
    fragColor = vec4(levelColour(hwLod.x) * (0.35 + 0.65 * dot(tex.rgb, vec3(0.333))), 1.0);
    return;
  }
  if (VIEW_ == 2) {  // anisotropic probes N per EXT_texture_filter_anisotropic, colourised
    float px = length(dx * vec2(uTexSize)), py = length(dy * vec2(uTexSize));
    float n = min(ceil(max(px, py) / max(min(px, py), 1e-8)), uMaxAniso);
    fragColor = vec4(levelColour(log2(max(n, 1.0)) * 1.75) * (0.35 + 0.65 * dot(tex.rgb, vec3(0.333))), 1.0);
    return;
  }
  if (VIEW_ == 3) {
    fragColor = vec4(tex.rgb, 1.0);
    return;
  }

  // ---- lighting with an (optionally normal-mapped) normal; one point light ----
  vec3 N = normalize(vNormal);
  vec3 V = normalize(uEye - vWorldPos);
  if (dot(N, V) < 0.0) N = -N;
  if (NORMAL_MAPPING_) {
    vec3 m = texture(uNormalMap, uv).xyz * 2.0 - 1.0;
    N = normalize(cotangentFrame(N, vWorldPos, uv) * m);
  }
  vec3 L = normalize(uLightPos - vWorldPos);
  vec3 H = normalize(L + V);
  float diffuse = max(dot(N, L), 0.0);
  float spec = diffuse > 0.0 ? 0.25 * pow(max(dot(N, H), 0.0), 32.0) : 0.0;
  vec3 lit = uMaterial * (0.45 + 0.55 * diffuse) + vec3(spec);

  // ---- combination with the material ([Tarantsev-L12], interaction with the material) ----
  vec3 ct = tex.rgb;
  float at = tex.a;
  if (CHANNELS_ == 1) ct = vec3(dot(tex.rgb, vec3(0.299, 0.587, 0.114)));
  if (CHANNELS_ == 2) {  // alpha only: colour from the material, coverage from the texture
    at = dot(tex.rgb, vec3(0.299, 0.587, 0.114));
    ct = vec3(1.0);
  }
  vec3 c;
  if (COMBINE_ == 0) c = CHANNELS_ == 2 ? lit : ct;              // replace: the texture, no lighting
  else if (COMBINE_ == 1) c = lit * ct;                          // modulate
  else c = lit * (vec3(1.0) - ct) + uEnvColor * ct;               // blend: C_f (1 - C_t) + C_c C_t
  if (CHANNELS_ == 2) c = mix(uSky, c, at);
  fragColor = vec4(c, 1.0);
}

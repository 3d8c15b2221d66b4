#include "algorithms/shadow_math.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/lighting.hpp"

namespace shadowlab::shadow {

namespace {
bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
float planeDistance(const glm::vec4& plane, const glm::vec3& p) { return glm::dot(glm::vec3(plane), p) + plane.w; }

// The faces of a volume as cyclic corner lists (see ConvexVolume's corner numbering), in the order
// of its planes: -x, +x, -y, +y, -z, +z.
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};

void planesFromCorners(ConvexVolume& v) {
  glm::vec3 centre(0.0f);
  for (const glm::vec3& c : v.corners) centre += c / 8.0f;
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 a = v.corners[kFaces[f][0]], b = v.corners[kFaces[f][1]], c = v.corners[kFaces[f][2]],
                    d = v.corners[kFaces[f][3]];
    // Newell's normal: robust for the tiny near face of a frustum with a huge far/near ratio.
    glm::vec3 n = glm::cross(c - a, d - b);
    const float len = glm::length(n);
    if (!(len > 0.0f) || !std::isfinite(len))
      throw std::invalid_argument("convex volume: degenerate face " + std::to_string(f));
    n /= len;
    const glm::vec3 faceCentre = 0.25f * (a + b + c + d);
    if (glm::dot(n, centre - faceCentre) < 0.0f) n = -n;
    v.planes[std::size_t(f)] = glm::vec4(n, -glm::dot(n, faceCentre));
  }
}

// Sutherland-Hodgman against one plane (keeps points with distance >= -eps).
std::vector<glm::vec3> clip(const std::vector<glm::vec3>& poly, const glm::vec4& plane, float eps) {
  std::vector<glm::vec3> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3& p = poly[i];
    const glm::vec3& q = poly[(i + 1) % n];
    const float dp = planeDistance(plane, p), dq = planeDistance(plane, q);
    if (dp >= -eps) out.push_back(p);
    if ((dp >= -eps) != (dq >= -eps)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}
}  // namespace

glm::mat4 textureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView) {
  return lighting::ndcToTexture() * lightProjection * lightView;
}

glm::vec3 shadowCoord(const glm::mat4& m, const glm::vec3& p) {
  const glm::vec4 h = m * glm::vec4(p, 1.0f);
  return glm::vec3(h) / h.w;
}

float depthCompare(float fragmentDepth, float storedDepth, float bias) {
  return fragmentDepth - bias <= storedDepth ? 1.0f : 0.0f;
}

DepthMap::DepthMap(int w, int h, std::vector<float> d) : width(w), height(h), depth(std::move(d)) {
  if (w < 1 || h < 1)
    throw std::invalid_argument("depth map: size " + std::to_string(w) + "x" + std::to_string(h) + " is below 1x1");
  if (depth.size() != std::size_t(w) * std::size_t(h))
    throw std::invalid_argument("depth map: " + std::to_string(depth.size()) + " depths for " + std::to_string(w) +
                                "x" + std::to_string(h) + " texels");
}

DepthMap::DepthMap(int w, int h, float fill)
    : DepthMap(w, h, std::vector<float>(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)), fill)) {}

float DepthMap::at(int x, int y) const {
  x = std::clamp(x, 0, width - 1);
  y = std::clamp(y, 0, height - 1);
  return depth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
}

float shadowLookup(const DepthMap& map, const glm::vec3& uvz, float bias) {
  if (uvz.x < 0.0f || uvz.x > 1.0f || uvz.y < 0.0f || uvz.y > 1.0f || uvz.z > 1.0f) return 1.0f;
  const int x = int(std::floor(uvz.x * float(map.width)));
  const int y = int(std::floor(uvz.y * float(map.height)));
  return depthCompare(uvz.z, map.at(x, y), bias);
}

float slopeScaledBias(float constant, float slope, float cosTheta, float maxBias) {
  if (!(cosTheta > 0.0f)) return maxBias;
  const float c = std::min(cosTheta, 1.0f);
  const float tanTheta = std::sqrt(1.0f - c * c) / c;
  return std::min(constant + slope * tanTheta, maxBias);
}

glm::vec4 bilinearPcfWeights(const glm::vec2& texel) {
  const glm::vec2 t = texel - 0.5f;
  const glm::vec2 f = t - glm::floor(t);
  return {(1 - f.x) * (1 - f.y), f.x * (1 - f.y), (1 - f.x) * f.y, f.x * f.y};
}

float bilinearPcfLookup(const DepthMap& map, const glm::vec3& uvz, float bias) {
  if (uvz.z > 1.0f) return 1.0f;
  const glm::vec2 texel(uvz.x * float(map.width), uvz.y * float(map.height));
  const glm::vec4 w = bilinearPcfWeights(texel);
  const int x0 = int(std::floor(texel.x - 0.5f)), y0 = int(std::floor(texel.y - 0.5f));
  return w[0] * depthCompare(uvz.z, map.at(x0, y0), bias) + w[1] * depthCompare(uvz.z, map.at(x0 + 1, y0), bias) +
         w[2] * depthCompare(uvz.z, map.at(x0, y0 + 1), bias) +
         w[3] * depthCompare(uvz.z, map.at(x0 + 1, y0 + 1), bias);
}

float boxPcfLookup(const DepthMap& map, const glm::vec3& uvz, float bias, int n) {
  if (n < 1 || n % 2 == 0)
    throw std::invalid_argument("PCF kernel size " + std::to_string(n) + " must be odd and >= 1");
  if (uvz.z > 1.0f) return 1.0f;
  const int cx = int(std::floor(uvz.x * float(map.width))), cy = int(std::floor(uvz.y * float(map.height)));
  float lit = 0.0f;
  for (int dy = -n / 2; dy <= n / 2; ++dy)
    for (int dx = -n / 2; dx <= n / 2; ++dx) lit += depthCompare(uvz.z, map.at(cx + dx, cy + dy), bias);
  return lit / float(n * n);
}

int cubeFace(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x == 0.0f && a.y == 0.0f && a.z == 0.0f) return -1;
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

glm::vec2 cubeFaceUv(const glm::vec3& d) {
  float sc = 0, tc = 0, ma = 1;
  switch (cubeFace(d)) {
    case 0:
      sc = -d.z;
      tc = -d.y;
      ma = d.x;
      break;
    case 1:
      sc = d.z;
      tc = -d.y;
      ma = d.x;
      break;
    case 2:
      sc = d.x;
      tc = d.z;
      ma = d.y;
      break;
    case 3:
      sc = d.x;
      tc = -d.z;
      ma = d.y;
      break;
    case 4:
      sc = d.x;
      tc = -d.y;
      ma = d.z;
      break;
    case 5:
      sc = -d.x;
      tc = -d.y;
      ma = d.z;
      break;
    default: return glm::vec2(0.5f);
  }
  const float m = std::abs(ma);
  return {0.5f * (sc / m + 1.0f), 0.5f * (tc / m + 1.0f)};
}

glm::mat4 cubeFaceView(const glm::vec3& p, int face) {
  static const glm::vec3 forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  if (face < 0 || face > 5) throw std::invalid_argument("cube face " + std::to_string(face) + " is not in 0..5");
  return glm::lookAt(p, p + forward[face], up[face]);
}

float cubeDepth(float majorAxis, float n, float f) {
  const float ndc = (f + n) / (f - n) - 2.0f * f * n / ((f - n) * majorAxis);
  return 0.5f * ndc + 0.5f;
}

ConvexVolume volumeFromViewProj(const glm::mat4& viewProj) {
  if (std::abs(glm::determinant(viewProj)) < 1e-30f || !finite(viewProj))
    throw std::invalid_argument("convex volume: the view-projection matrix is singular or not finite");
  const glm::mat4 inv = glm::inverse(viewProj);
  ConvexVolume v;
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 h = inv * glm::vec4(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f, 1.0f);
    v.corners[std::size_t(i)] = glm::vec3(h) / h.w;
  }
  planesFromCorners(v);
  return v;
}

ConvexVolume volumeFromBox(const Aabb& box) {
  if (box.empty()) throw std::invalid_argument("convex volume: the box is empty");
  ConvexVolume v;
  for (int i = 0; i < 8; ++i)
    v.corners[std::size_t(i)] = {i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                 i & 4 ? box.max.z : box.min.z};
  v.planes = {glm::vec4(1, 0, 0, -box.min.x), glm::vec4(-1, 0, 0, box.max.x), glm::vec4(0, 1, 0, -box.min.y),
              glm::vec4(0, -1, 0, box.max.y), glm::vec4(0, 0, 1, -box.min.z), glm::vec4(0, 0, -1, box.max.z)};
  return v;
}

bool volumesMayIntersect(const ConvexVolume& a, const ConvexVolume& b) {
  auto separates = [](const glm::vec4& plane, const ConvexVolume& other) {
    for (const glm::vec3& c : other.corners)
      if (planeDistance(plane, c) >= 0.0f) return false;
    return true;
  };
  for (const glm::vec4& p : a.planes)
    if (separates(p, b)) return false;
  for (const glm::vec4& p : b.planes)
    if (separates(p, a)) return false;
  return true;
}

std::vector<glm::vec3> intersectionPoints(const ConvexVolume& a, const ConvexVolume& b) {
  std::vector<glm::vec3> out;
  auto clipFaces = [&out](const ConvexVolume& faces, const ConvexVolume& by) {
    float scale = 0.0f;
    for (const glm::vec3& c : faces.corners) scale = std::max(scale, glm::length(c));
    const float eps = 1e-5f * std::max(scale, 1.0f);
    for (const auto& f : kFaces) {
      std::vector<glm::vec3> poly{faces.corners[std::size_t(f[0])], faces.corners[std::size_t(f[1])],
                                  faces.corners[std::size_t(f[2])], faces.corners[std::size_t(f[3])]};
      for (const glm::vec4& plane : by.planes) {
        poly = clip(poly, plane, eps);
        if (poly.empty()) break;
      }
      out.insert(out.end(), poly.begin(), poly.end());
    }
  };
  clipFaces(a, b);
  clipFaces(b, a);
  return out;
}

bool casterMayShadow(const Aabb& caster, const ConvexVolume& view, const glm::vec3& lightDirection) {
  for (const glm::vec4& plane : view.planes) {
    const glm::vec3 n(plane);
    // The box's corner farthest along n: if even it is outside, the whole box is.
    const glm::vec3 far{n.x >= 0 ? caster.max.x : caster.min.x, n.y >= 0 ? caster.max.y : caster.min.y,
                        n.z >= 0 ? caster.max.z : caster.min.z};
    if (planeDistance(plane, far) < 0.0f && glm::dot(n, lightDirection) <= 0.0f) return false;
  }
  return true;
}

glm::mat4 lightViewAlong(const glm::vec3& eye, const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::lookAt(eye, eye + d, up);
}

TexelSnap snapToTexels(const glm::vec2& centre, const glm::vec2& half, int mapSize) {
  // Square, quantised size (changes only when the view's extent crosses a step) and a centre on
  // the texel grid: the map's texels stay put in the world while the camera moves.
  TexelSnap s;
  float h = std::max({half.x, half.y, 1e-3f}) * (1.0f + 2.0f / float(mapSize));
  const float step = std::exp2(std::ceil(std::log2(h))) / 4.0f;
  h = std::ceil(h / step) * step;
  const float texel = 2.0f * h / float(mapSize);
  s.centre = glm::round(centre / texel) * texel;
  s.half = h;
  return s;
}

OrthoFit fitOrthographic(const glm::vec3& lightDirection, std::span<const glm::vec3> receivers,
                         std::span<const Aabb> casters, int mapSize, bool snap, const TexelSnapper& snapper) {
  if (receivers.empty()) throw std::invalid_argument("orthographic fit: no receiver points");
  if (!(glm::length(lightDirection) > 0.0f))
    throw std::invalid_argument("orthographic fit: the light direction is zero");
  if (mapSize < 1) throw std::invalid_argument("orthographic fit: map size " + std::to_string(mapSize) + " is below 1");
  OrthoFit fit;
  fit.view = lightViewAlong(glm::vec3(0.0f), lightDirection);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : receivers) {
    const glm::vec3 l = glm::vec3(fit.view * glm::vec4(p, 1.0f));
    lo = glm::min(lo, l);
    hi = glm::max(hi, l);
  }
  // Casters toward the light (larger light-space z: the light looks down -z) push the near plane out.
  for (const Aabb& b : casters)
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c{i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
      hi.z = std::max(hi.z, (fit.view * glm::vec4(c, 1.0f)).z);
    }
  glm::vec2 centre = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
  glm::vec2 half = 0.5f * (glm::vec2(hi) - glm::vec2(lo));
  if (snap) {
    const TexelSnap s = snapper ? snapper(centre, half, mapSize) : snapToTexels(centre, half, mapSize);
    // A snap that returns no size (a stub): a tiny map that covers nothing, never a NaN matrix.
    const float h = std::isfinite(s.half) && s.half > 0.0f ? s.half : 1e-3f;
    centre = std::isfinite(s.centre.x) && std::isfinite(s.centre.y) ? s.centre : centre;
    half = glm::vec2(h);
  } else {
    half = glm::max(half, glm::vec2(1e-3f));
  }
  const float depthMargin = 0.01f + 0.005f * (hi.z - lo.z);
  fit.lightMin = {centre - half, lo.z - depthMargin};
  fit.lightMax = {centre + half, hi.z + depthMargin};
  fit.projection =
      glm::ortho(fit.lightMin.x, fit.lightMax.x, fit.lightMin.y, fit.lightMax.y, -fit.lightMax.z, -fit.lightMin.z);
  fit.texelWorld = 2.0f * std::max(half.x, half.y) / float(mapSize);
  return fit;
}

std::span<const glm::vec2> poissonDisk() {
  // The widely used 16-point set (within [-1,1]^2, roughly a disk); shaders/03_shadow_quality/scene.frag.
  static const glm::vec2 disk[16] = {
      {-0.94201624f, -0.39906216f}, {0.94558609f, -0.76890725f},  {-0.094184101f, -0.92938870f},
      {0.34495938f, 0.29387760f},   {-0.91588581f, 0.45771432f},  {-0.81544232f, -0.87912464f},
      {-0.38277543f, 0.27676845f},  {0.97484398f, 0.75648379f},   {0.44323325f, -0.97511554f},
      {0.53742981f, -0.47373420f},  {-0.26496911f, -0.41893023f}, {0.79197514f, 0.19090188f},
      {-0.24188840f, 0.99706507f},  {-0.81409955f, 0.91437590f},  {0.19984126f, 0.78641367f},
      {0.14383161f, -0.14100790f}};
  return disk;
}

float rotationAngle(const glm::vec2& pixel) {
  const float h = std::sin(glm::dot(pixel, glm::vec2(12.9898f, 78.233f))) * 43758.5453f;
  return (h - std::floor(h)) * 6.28318530718f;
}

bool boxOutsideClip(const glm::mat4& viewProj, const Aabb& box) {
  if (box.empty()) return true;
  unsigned outside = 0x3f;  // bit k: every corner so far is outside plane k
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = viewProj * glm::vec4(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                             i & 4 ? box.max.z : box.min.z, 1.0f);
    unsigned here = 0;
    for (int a = 0; a < 3; ++a) {
      if (c[a] < -c.w) here |= 1u << (2 * a);
      if (c[a] > c.w) here |= 2u << (2 * a);
    }
    outside &= here;
    if (!outside) return false;
  }
  return true;
}

}  // namespace shadowlab::shadow

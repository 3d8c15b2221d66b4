#include "algorithms/psm/cube_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "algorithms/psm/clipping.hpp"

namespace shadowlab::psm {

namespace {

void checkFace(int face) {
  if (face < 0 || face > 5) throw std::invalid_argument("cube face = " + std::to_string(face) + " is not in 0..5");
}

// Tangents (t1, t2) with t1 x t2 = -n, so view axes (t1, t2, -n) are right-handed and the face
// camera looks along +n.
void faceTangents(int face, glm::dvec3& t1, glm::dvec3& t2) {
  const glm::dvec3 n = cubeFaceNormal(face);
  t2 = (face == 2 || face == 3) ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  t1 = glm::cross(t2, -n);
}

std::array<glm::dvec3, 4> faceCorners(int face) {
  const glm::dvec3 n = cubeFaceNormal(face);
  glm::dvec3 t1, t2;
  faceTangents(face, t1, t2);
  return {n - t1 - t2, n + t1 - t2, n + t1 + t2, n - t1 + t2};
}

}  // namespace

glm::dvec3 cubeFaceNormal(int face) {
  checkFace(face);
  glm::dvec3 n(0.0);
  n[face / 2] = (face % 2 == 0) ? 1.0 : -1.0;
  return n;
}

bool cubeFaceVisible(int face, const PostProjectiveLight& light) {
  const glm::dvec3 n = cubeFaceNormal(face);
  // A direction grazing a face (|n.D| tiny, e.g. rounding of an axis-aligned light) would give
  // that face an ill-conditioned oblique projection; rays then leave through the other faces.
  if (light.kind == PostLightKind::Direction) return glm::dot(n, light.direction) >= -1e-9;
  return glm::dot(n, light.position) >= 1.0;
}

unsigned hiddenFaceMask(const PostProjectiveLight& light) {
  unsigned m = 0;
  for (int f = 0; f < 6; ++f)
    if (!cubeFaceVisible(f, light)) m |= 1u << f;
  return m;
}

unsigned hiddenFaceMask(const PostProjectiveLight& light, const PsmSteps& steps) {
  if (!steps.faceVisible) return hiddenFaceMask(light);
  unsigned m = 0;
  for (int f = 0; f < 6; ++f)
    if (!steps.faceVisible(f, light)) m |= 1u << f;
  return m;
}

int hiddenFaceCount(const PostProjectiveLight& light) {
  int c = 0;
  for (unsigned m = hiddenFaceMask(light); m; m &= m - 1) ++c;
  return c;
}

int cubeFaceOf(const glm::dvec3& point, const PostProjectiveLight& light) {
  return cubeFaceOf(point, light, hiddenFaceMask(light));
}

int cubeFaceOf(const glm::dvec3& point, const PostProjectiveLight& light, unsigned hiddenMask) {
  const bool dir = light.kind == PostLightKind::Direction;
  const glm::dvec3 v = dir ? -light.direction : point - light.position;
  const glm::dvec3 origin = dir ? point : light.position;
  int best = -1;
  double bestT = std::numeric_limits<double>::max();
  for (int f = 0; f < 6; ++f) {
    const glm::dvec3 n = cubeFaceNormal(f);
    const double nv = glm::dot(n, v);
    if (!(nv > 0.0) || !(hiddenMask & (1u << f))) continue;
    const double t = (1.0 - glm::dot(n, origin)) / nv;
    if (t < bestT) {
      bestT = t;
      best = f;
    }
  }
  return best;
}

glm::dvec3 cubeLookupVector(const glm::dvec3& point, const PostProjectiveLight& light) {
  return light.kind == PostLightKind::Direction ? -light.direction : point - light.position;
}

double cubeFaceRegionMinDistance(const glm::dvec3& L, int face) {
  const glm::dvec3 n = cubeFaceNormal(face);
  if (glm::all(glm::lessThanEqual(glm::abs(L), glm::dvec3(1.0)))) return 0.0;
  // Vertices of cube ∩ pyramid(L, face): cube faces clipped by the pyramid's sides, and the
  // pyramid's side triangles clipped by the cube.
  const auto fc = faceCorners(face);
  Plane side[4];
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 a = fc[i], b = fc[(i + 1) % 4];
    glm::dvec3 nn = glm::cross(a - L, b - L);
    nn /= glm::length(nn);
    side[i] = Plane{nn, -glm::dot(nn, L)};
    if (side[i].distance(n) < 0.0) side[i] = Plane{-nn, -side[i].offset};
  }
  const Plane cube[6] = {{{-1, 0, 0}, 1}, {{1, 0, 0}, 1},  {{0, -1, 0}, 1},
                         {{0, 1, 0}, 1},  {{0, 0, -1}, 1}, {{0, 0, 1}, 1}};
  double best = std::numeric_limits<double>::max();
  glm::dvec3 bufA[kMaxPolygon], bufB[kMaxPolygon];
  auto run = [&](int count, const Plane* planes, int np) {
    glm::dvec3* cur = bufA;
    glm::dvec3* nxt = bufB;
    for (int k = 0; k < np && count > 0; ++k) {
      count = clipPolygon(cur, count, planes[k], nxt);
      std::swap(cur, nxt);
    }
    for (int k = 0; k < count; ++k) best = std::min(best, glm::dot(n, cur[k] - L));
  };
  for (int g = 0; g < 6; ++g) {
    const auto gc = faceCorners(g);
    for (int k = 0; k < 4; ++k) bufA[k] = gc[k];
    run(4, side, 4);
  }
  for (int i = 0; i < 4; ++i) {
    bufA[0] = L;
    bufA[1] = fc[i];
    bufA[2] = fc[(i + 1) % 4];
    run(3, cube, 6);
  }
  return std::max(best, 0.0);
}

namespace {

// A direction light: an oblique orthographic projection along the light onto face n: mu = the
// distance (in units of |D| = 1) travelled along -D from the point to the face.
void directionFaceCamera(const glm::dvec3& n, const glm::dvec3& t1, const glm::dvec3& t2, const glm::dvec3& D,
                         const glm::dmat4& remap, LightCamera& cam) {
  const double nD = glm::dot(n, D);  // < 0 for a hidden face
  const double muMax = 2.0 / -nD * (1.0 + 1e-9);
  glm::dmat4 m(0.0);
  // u = t1.X - (t1.D / nD)(n.X - 1), v likewise, mu = (n.X - 1) / nD, depth = 1 - 2 mu / muMax.
  const glm::dvec3 ru = t1 - (glm::dot(t1, D) / nD) * n;
  const glm::dvec3 rv = t2 - (glm::dot(t2, D) / nD) * n;
  const glm::dvec3 rm = n / nD;
  for (int c = 0; c < 3; ++c) {
    m[c][0] = ru[c];
    m[c][1] = rv[c];
    m[c][2] = -2.0 / muMax * rm[c];
  }
  m[3][0] = glm::dot(t1, D) / nD;
  m[3][1] = glm::dot(t2, D) / nD;
  m[3][2] = 1.0 + 2.0 / muMax / nD;
  m[3][3] = 1.0;
  cam.kind = LightProjection::Orthographic;
  cam.eye = glm::dvec3(0.0);
  cam.view = glm::dmat4(1.0);
  cam.projection = remap * m;
  cam.zNear = 0.0;
  cam.zFar = muMax;
}

// A finite light: the off-centre frustum from L whose far plane is the face (in front), or fix 1's
// inverse projection with a = the closest point it serves (behind).
void pointFaceCamera(int f, const glm::dvec3& t1, const glm::dvec3& t2, const PostProjectiveLight& light,
                     double closestReceiver, const PsmOptions& opt, LightCamera& cam) {
  const glm::dvec3 n = cubeFaceNormal(f);
  const glm::dvec3 L = light.position;
  cam.eye = L;
  glm::dmat4 view(1.0);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = t1[c];
    view[c][1] = t2[c];
    view[c][2] = -n[c];
  }
  view[3] = glm::dvec4(-glm::dot(t1, L), -glm::dot(t2, L), glm::dot(n, L), 1.0);
  cam.view = view;
  const double D = 1.0 - glm::dot(n, L);  // distance from the light to the face plane, > 0
  // Slopes of the face square as seen from the light: x/Z in [sl, sr], y/Z in [sb, st].
  const double sl = (-1.0 - glm::dot(t1, L)) / D, sr = (1.0 - glm::dot(t1, L)) / D;
  const double sb = (-1.0 - glm::dot(t2, L)) / D, st = (1.0 - glm::dot(t2, L)) / D;
  glm::dmat4 p(0.0);
  p[0][0] = 2.0 / (sr - sl);
  p[2][0] = (sr + sl) / (sr - sl);
  p[1][1] = 2.0 / (st - sb);
  p[2][1] = (st + sb) / (st - sb);
  p[2][3] = -1.0;
  const double geo = cubeFaceRegionMinDistance(L, f);
  const double closest = std::min(geo > 0.0 ? geo : std::numeric_limits<double>::max(), closestReceiver);
  if (light.kind == PostLightKind::InFront) {
    const double zf = D * (1.0 + 1e-9);
    const double zn = closest < zf ? opt.nearFraction * closest : 1e-3 * D;
    p[2][2] = -(zf + zn) / (zf - zn);
    p[3][2] = -2.0 * zf * zn / (zf - zn);
    cam.kind = LightProjection::Perspective;
    cam.zNear = zn;
    cam.zFar = zf;
  } else {
    const double a = (closest < D ? closest : D) * (1.0 - 1e-9);
    p[3][2] = a;
    cam.kind = LightProjection::Inverse;
    cam.zNear = -a;
    cam.zFar = a;
  }
  cam.projection = depthRangeRemap(opt.depthRange) * p;
}

}  // namespace

CubeFaceSet cubeFaceCameras(const PostProjectiveLight& light, const glm::dmat4& cameraViewProj,
                            std::span<const glm::dvec3> postReceivers, const PsmOptions& opt) {
  CubeFaceSet set;
  set.light = light;
  set.hiddenMask = hiddenFaceMask(light, opt.steps);
  // The closest receiver per face (a light inside the cube has no geometric bound).
  std::array<double, 6> recvMin;
  recvMin.fill(std::numeric_limits<double>::max());
  if (light.kind != PostLightKind::Direction)
    for (const auto& p : postReceivers) {
      const int f = cubeFaceOf(p, light, set.hiddenMask);
      if (f >= 0) recvMin[f] = std::min(recvMin[f], glm::dot(cubeFaceNormal(f), p - light.position));
    }
  for (int f = 0; f < 6; ++f) {
    if (!(set.hiddenMask & (1u << f))) continue;
    // A face the light sees (a student's visibility test may call it hidden) holds no map: from
    // its outer side no frustum reaches the cube through it.
    const double facing = light.kind == PostLightKind::Direction ? -glm::dot(cubeFaceNormal(f), light.direction)
                                                                 : 1.0 - glm::dot(cubeFaceNormal(f), light.position);
    if (!(facing > 1e-12)) continue;
    CubeFaceCamera& fc = set.faces[f];
    fc.used = true;
    LightCamera& cam = fc.camera;
    glm::dvec3 t1, t2;
    faceTangents(f, t1, t2);
    cam.axis = cubeFaceNormal(f);
    if (light.kind == PostLightKind::Direction)
      directionFaceCamera(cam.axis, t1, t2, light.direction, depthRangeRemap(opt.depthRange), cam);
    else pointFaceCamera(f, t1, t2, light, recvMin[f], opt, cam);
    cam.postToClip = cam.projection * cam.view;
    cam.worldToClip = cam.postToClip * cameraViewProj;
  }
  return set;
}

}  // namespace shadowlab::psm

#include "algorithms/sdsm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <span>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab::shadow {
namespace {

void requireShape(const DepthTiles& t) {
  if (t.width < 0 || t.height < 0 || t.depths.size() != std::size_t(t.width) * std::size_t(t.height))
    throw std::invalid_argument("depth tiles: " + std::to_string(t.depths.size()) + " depths for " +
                                std::to_string(t.width) + " x " + std::to_string(t.height) + " tiles");
  if (t.tilePixels < 1 || t.pixelsWide < 1 || t.pixelsHigh < 1)
    throw std::invalid_argument("depth tiles: tiles of " + std::to_string(t.tilePixels) + " pixels over a " +
                                std::to_string(t.pixelsWide) + " x " + std::to_string(t.pixelsHigh) + " frame");
}

}  // namespace

DepthRange depthRange(const DepthTiles& t) {
  requireShape(t);
  DepthRange r{INFINITY, -INFINITY, 0};
  for (const glm::vec2& d : t.depths) {
    if (!(d.x <= d.y)) continue;  // nothing drawn there (NaN included)
    r.nearest = std::min(r.nearest, double(d.x));
    r.farthest = std::max(r.farthest, double(d.y));
    ++r.tiles;
  }
  return r;
}

void tileCorners(const DepthTiles& t, int x, int y, double a, double b, std::vector<glm::vec3>& out) {
  // The tile's pixels as normalised device coordinates, its edges as rays through the eye: at view
  // depth z a point of NDC (u, v) sits at (u z tan_x, v z tan_y, -z) in the camera's frame.
  const double px0 = double(x) * t.tilePixels, px1 = std::min(double(x + 1) * t.tilePixels, double(t.pixelsWide));
  const double py0 = double(y) * t.tilePixels, py1 = std::min(double(y + 1) * t.tilePixels, double(t.pixelsHigh));
  const double u[2] = {2.0 * px0 / t.pixelsWide - 1.0, 2.0 * px1 / t.pixelsWide - 1.0};
  const double v[2] = {2.0 * py0 / t.pixelsHigh - 1.0, 2.0 * py1 / t.pixelsHigh - 1.0};
  const double tanY = std::tan(0.5 * double(t.viewer.fovY)), tanX = tanY * double(t.viewer.aspect);
  const glm::dmat4 toWorld = glm::inverse(glm::dmat4(t.viewer.view));
  for (const double z : {a, b})
    for (int k = 0; k < 4; ++k) {
      const glm::dvec4 p(u[k & 1] * z * tanX, v[k >> 1] * z * tanY, -z, 1.0);
      out.push_back(glm::vec3(toWorld * p));
    }
}

SdsmFit fitSampleDistribution(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& viewer,
                              const DepthTiles& tiles, const SdsmOptions& o) {
  SdsmFit fit;
  fit.range = depthRange(tiles);
  const CascadeOptions& c = o.cascades;
  if (fit.range.tiles == 0) {  // nothing on screen to fit to: the practical cascades
    fit.fellBack = true;
    fit.set = fitCascades(direction, scene, viewer, c);
    if (!fit.set.splits.empty()) fit.zNear = fit.set.splits.front(), fit.zFar = fit.set.splits.back();
    return fit;
  }
  const double zn = double(viewer.nearZ), zf = double(viewer.farZ);
  fit.zNear = std::clamp(fit.range.nearest * (1.0 - o.margin), zn, zf);
  fit.zFar = std::clamp(fit.range.farthest * (1.0 + o.margin), fit.zNear * 1.001, std::max(zf, fit.zNear * 1.001));
  std::vector<double> splits = c.splitter ? c.splitter(fit.zNear, fit.zFar, c.count, c.lambda)
                                          : cascadeSplits(fit.zNear, fit.zFar, c.count, c.lambda);
  // Cascade i's receivers: every tile's piece of the frustum within [split i less the blend band
  // that cascade i - 1 mixes into it, split i + 1] and within the tile's own depths (widened). Those
  // pieces reach past the scene's bounds (a tile's far corners beside the ground's edge), which the
  // slice's own fit does not: the samples lie inside both, so the map covers the light-space box
  // where the two boxes overlap, handed over as its eight corners.
  CascadeReceivers receivers;
  std::vector<glm::vec3> pieces;
  const glm::mat4 toLight = lightViewAlong(glm::vec3(0.0f), direction);
  const glm::mat4 fromLight = glm::inverse(toLight);
  const auto lightBox = [&](std::span<const glm::vec3> points, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(INFINITY), hi = glm::vec3(-INFINITY);
    for (const glm::vec3& p : points) {
      const glm::vec3 l(toLight * glm::vec4(p, 1.0f));
      lo = glm::min(lo, l), hi = glm::max(hi, l);
    }
  };
  if (o.tightFit)
    receivers = [&](int i, std::vector<glm::vec3>& out) {
      const std::vector<double>& s = splits;
      const double lead = i == 0 ? 0.0 : o.band * (s[std::size_t(i)] - s[std::size_t(i) - 1]);
      const double lo = s[std::size_t(i)] - lead, hi = s[std::size_t(i) + 1];
      pieces.clear();
      for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x) {
          const glm::vec2 d = tiles.depths[std::size_t(y) * std::size_t(tiles.width) + std::size_t(x)];
          if (!(d.x <= d.y)) continue;
          const double a = std::max(double(d.x) * (1.0 - o.margin), lo);
          const double b = std::min(double(d.y) * (1.0 + o.margin), hi);
          if (a <= b) tileCorners(tiles, x, y, a, b, pieces);
        }
      if (pieces.empty()) return;  // nothing seen in this slice: its whole slice's fit
      const glm::mat4 slice = glm::perspective(viewer.fovY, viewer.aspect, float(lo), float(hi)) * viewer.view;
      const std::vector<glm::vec3> wide = intersectionPoints(volumeFromBox(scene.bounds), volumeFromViewProj(slice));
      glm::vec3 lo1, hi1, lo2, hi2;
      lightBox(pieces, lo1, hi1);
      if (!wide.empty()) {
        lightBox(wide, lo2, hi2);
        lo1 = glm::max(lo1, lo2), hi1 = glm::min(hi1, hi2);
        if (glm::any(glm::greaterThan(lo1, hi1))) lightBox(pieces, lo1, hi1);  // rounding: keep the pieces'
      }
      for (int k = 0; k < 8; ++k)
        out.push_back(glm::vec3(
            fromLight * glm::vec4((k & 1) ? hi1.x : lo1.x, (k & 2) ? hi1.y : lo1.y, (k & 4) ? hi1.z : lo1.z, 1.0f)));
    };
  fit.set = fitCascadesOver(splits, fit.zNear, fit.zFar, direction, scene, viewer, c, receivers);  // a copy
  return fit;
}

}  // namespace shadowlab::shadow

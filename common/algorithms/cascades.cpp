#include "algorithms/cascades.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/psm/clipping.hpp"
#include "algorithms/psm/lispsm.hpp"

namespace shadowlab::shadow {

void cascadeSplits(double zn, double zf, int count, double lambda, std::vector<double>& out) {
  if (!std::isfinite(zn) || zn <= 0.0) throw std::invalid_argument("zNear = " + std::to_string(zn) + " must be > 0");
  if (!std::isfinite(zf) || zf <= zn) throw std::invalid_argument("zFar = " + std::to_string(zf) + " must be > zNear");
  if (count < 1) throw std::invalid_argument("count = " + std::to_string(count) + " must be >= 1");
  if (!(lambda >= 0.0 && lambda <= 1.0))
    throw std::invalid_argument("lambda = " + std::to_string(lambda) + " must be in [0,1]");
  out.resize(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const double t = static_cast<double>(i) / count;
    const double logSplit = zn * std::pow(zf / zn, t);
    const double uniSplit = zn + (zf - zn) * t;
    out[i] = lambda * logSplit + (1.0 - lambda) * uniSplit;
  }
  out.front() = zn;  // exact ends, whatever pow rounds to
  out.back() = zf;
}

std::vector<double> cascadeSplits(double zn, double zf, int count, double lambda) {
  std::vector<double> out;
  cascadeSplits(zn, zf, count, lambda, out);
  return out;
}

CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band) {
  CascadeBlend b;
  if (splits.size() < 2 || !(depth >= splits.front()) || depth > splits.back()) return b;
  const int last = int(splits.size()) - 2;
  b.cascade = 0;
  while (b.cascade < last && depth > splits[std::size_t(b.cascade) + 1]) ++b.cascade;
  if (b.cascade == last || band <= 0.0) return b;
  const double zFar = splits[std::size_t(b.cascade) + 1];
  const double width = band * (zFar - splits[std::size_t(b.cascade)]);
  const double start = zFar - width;
  if (depth > start) b.nextWeight = std::min((depth - start) / width, 1.0);
  return b;
}

int cascadeSide(int totalSide, int count) {
  if (count < 1) throw std::invalid_argument("cascade count = " + std::to_string(count) + " must be >= 1");
  if (totalSide < 1) throw std::invalid_argument("total side = " + std::to_string(totalSide) + " must be >= 1");
  return std::max(1, int(std::floor(double(totalSide) / std::sqrt(double(count)) + 1e-9)));
}

double cascadeFar(const CascadeViewer& v, const Aabb& b) {
  double deepest = 0.0;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
    deepest = std::max(deepest, -double((v.view * glm::vec4(corner, 1.0f)).z));
  }
  if (deepest <= double(v.nearZ)) return double(v.farZ);
  return std::min(deepest, double(v.farZ));
}

namespace {

// Why `s` cannot be the splits of `count` cascades from zn to zf ("": it can).
std::string splitProblem(const std::vector<double>& s, int count, double zn, double zf) {
  if (int(s.size()) != count + 1)
    return "the split scheme gave " + std::to_string(s.size()) + " distances, " + std::to_string(count + 1) + " wanted";
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!std::isfinite(s[i]) || (i > 0 && !(s[i] > s[i - 1])))
      return "the split distances are not finite and increasing at " + std::to_string(i);
  if (std::abs(s.front() - zn) > 1e-6 * zn || std::abs(s.back() - zf) > 1e-6 * zf)
    return "the splits do not run from the near distance to the far one";
  return "";
}

// The union of the cascades' casters (each slice's own test), then each cascade's pass: those of
// them that can meet its light volume (its box moved back toward the light over the whole scene).
void cullPerCascade(CascadeSet& set, const CasterBoxes& scene, bool perCascade) {
  set.casters.assign(scene.casts.begin(), scene.casts.end());
  for (std::size_t k = 0; k < set.casters.size(); ++k) {
    if (!set.casters[k]) continue;
    bool any = false;
    for (const LightCamera& cam : set.cameras) any = any || cam.casters[k];
    set.casters[k] = any;
    set.culled += !any;
  }
  for (LightCamera& cam : set.cameras)
    cullAgainst(cam, scene, orthoVolumeToward(cam, scene.bounds), perCascade, set.casters);
}

}  // namespace

CascadeSet fitCascades(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& v,
                       const CascadeOptions& o) {
  if (o.count < 1 || o.count > 4)
    throw std::invalid_argument("cascade count = " + std::to_string(o.count) + " must be 1..4");
  const double zFar = o.farZ > 0.0 ? std::min(o.farZ, double(v.farZ)) : cascadeFar(v, scene.bounds);
  const double zn = double(v.nearZ), zf = std::max(zFar, double(v.nearZ) * 1.001);
  std::vector<double> splits =
      o.splitter ? o.splitter(zn, zf, o.count, o.lambda) : cascadeSplits(zn, zf, o.count, o.lambda);
  return fitCascadesOver(std::move(splits), zn, zf, direction, scene, v, o, {});
}

CascadeSet fitCascadesOver(std::vector<double> splits, double zn, double zf, const glm::vec3& direction,
                           const CasterBoxes& scene, const CascadeViewer& v, const CascadeOptions& o,
                           const CascadeReceivers& receivers) {
  if (o.count < 1 || o.count > 4)
    throw std::invalid_argument("cascade count = " + std::to_string(o.count) + " must be 1..4");
  CascadeSet set;
  set.splits = std::move(splits);
  set.problem = splitProblem(set.splits, o.count, zn, zf);
  if (!set.problem.empty()) return set;
  std::vector<glm::vec3> points;
  for (int i = 0; i < o.count; ++i) {
    const glm::mat4 slice =
        glm::perspective(v.fovY, v.aspect, float(set.splits[std::size_t(i)]), float(set.splits[std::size_t(i) + 1]));
    points.clear();
    if (receivers) receivers(i, points);
    set.cameras.push_back(fitDirectionalTo(direction, scene, volumeFromViewProj(slice * v.view), points, o.fit));
  }
  cullPerCascade(set, scene, o.cullPerCascade);
  return set;
}

std::vector<CascadeWarp> warpCascades(const CascadeSet& set, const CascadeViewer& v, const glm::vec3& direction,
                                      std::span<const Aabb> receivers, double band) {
  if (set.splits.size() != set.cameras.size() + 1)
    throw std::invalid_argument("warpCascades: " + std::to_string(set.splits.size()) + " splits for " +
                                std::to_string(set.cameras.size()) + " cascades");
  std::vector<CascadeWarp> out(set.cameras.size());
  std::vector<glm::dvec3> points;
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].worldToClip = glm::dmat4(set.cameras[k].viewProj());
    const double lead = k == 0 ? 0.0 : band * (set.splits[k] - set.splits[k - 1]);
    const psm::CameraFrustum slice =
        psm::makeCamera(glm::dmat4(v.view), double(v.fovY), double(v.aspect), set.splits[k] - lead, set.splits[k + 1]);
    psm::receiverKeyPoints(receivers, psm::frustumFromViewProj(slice.viewProj, slice.invViewProj), points);
    if (points.empty()) continue;
    const psm::LispsmCamera fit = psm::fitLispsm(slice, glm::dvec3(direction), points);
    out[k] = {fit.worldToClip, true, fit.n};
  }
  return out;
}

}  // namespace shadowlab::shadow

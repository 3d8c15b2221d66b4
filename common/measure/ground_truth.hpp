#pragma once
// Reference visibility by ray casting (Embree 3): the ground truth every shadow technique is
// measured against. Rays start from the very surface points the rasteriser shaded (a read-back of
// the view's world-position and normal attachments), so the comparison is pixel for pixel.
//
// Ray origin epsilon. A shadow ray starts at  p + eps * N  (N the unit normal of the pixel) and is
// cut eps short of a point or spot light. eps = relativeEpsilon * |diagonal of the scene bounds|
// (default 1e-4: 1 mm in a 10 m scene), so it scales with the scene instead of depending on units;
// rebuild() recomputes it. It is large enough to step off the float-rounded surface the position
// buffer holds (a 32F attachment keeps ~7 digits) and small enough not to leak light through
// contact shadows thicker than eps.
//
// Alpha-tested cards: a material with alphaCutoff > 0 and a texture is tested in an Embree filter
// function. The alpha is sampled bilinearly with repeat wrapping at the hit's uv, interpolated from
// the mesh uvs with Embree's barycentrics; uv (0,0) is the first (top) row of the Image8 as stored,
// which is how glTexImage2D sees an image uploaded without flipping. alpha < cutoff: a hole.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.hpp"
#include "core/light.hpp"
#include "core/scene.hpp"

namespace shadowlab::measure {

// Per-pixel surface points of the current view, row 0 the TOP row (a GL read-back flipped on the
// way in, as image.hpp does). Pixels with covered == 0 are background and are skipped.
struct SurfaceBuffer {
  int width = 0, height = 0;
  std::vector<glm::vec3> position;  // world space
  std::vector<glm::vec3> normal;    // world space, unit
  std::vector<std::uint8_t> covered;

  SurfaceBuffer() = default;
  SurfaceBuffer(int w, int h);  // every pixel uncovered; throws std::invalid_argument on w,h < 0
  std::size_t index(int x, int y) const { return std::size_t(y) * width + x; }
  void set(int x, int y, const glm::vec3& p, const glm::vec3& n) {
    position[index(x, y)] = p;
    normal[index(x, y)] = n;
    covered[index(x, y)] = 1;
  }
  // Throws std::invalid_argument unless the three arrays hold width * height entries.
  void validate() const;
};

// From RGBA32F read-backs: position.xyz with position.w > 0 marking covered pixels, normal.xyz
// (renormalised here). Throws std::invalid_argument on size or channel mismatches.
SurfaceBuffer surfaceFromImages(const ImageF& position, const ImageF& normal);
// Every `factor`-th pixel (the centre sample of each factor x factor block): a reduced-resolution
// view for an interactive heatmap. factor >= 1.
SurfaceBuffer downsample(const SurfaceBuffer& surface, int factor);

// Values in the visibility images besides [0,1].
inline constexpr float kBackground = -2.0f;  // covered == 0
inline constexpr float kNotFacing = -1.0f;   // N.L <= 0 (or outside a spot light's outer cone):
                                             // unlit by shading alone, no shadow to measure

// Alpha-tested materials need their textures: a lookup from Material::texture to an image (alpha in
// channel 3 of RGBA images, channel 1 of grey+alpha ones). Returning nullptr is an error for an
// alpha-tested material. Images are copied at rebuild(), so they need not outlive it.
using TextureLookup = std::function<const Image8*(const std::string& name)>;

struct GroundTruthOptions {
  float relativeEpsilon = 1e-4f;  // ray origin offset as a fraction of the scene diagonal
  int threads = 0;                // 0: std::thread::hardware_concurrency()
};

class GroundTruth {
 public:
  GroundTruth(const Scene& scene, TextureLookup textures = {}, GroundTruthOptions options = {});
  GroundTruth(const Scene& scene, const std::map<std::string, Image8>& textures, GroundTruthOptions options = {});
  ~GroundTruth();
  GroundTruth(const GroundTruth&) = delete;
  GroundTruth& operator=(const GroundTruth&) = delete;

  // Rebuilds the BVH from `scene` (objects with castsShadow only). Queries never rebuild.
  void rebuild(const Scene& scene);
  // Rebuilds only when `revision` differs from the one of the last update() (a scene's edit
  // counter); returns whether it rebuilt.
  bool update(const Scene& scene, std::uint64_t revision);
  std::uint64_t buildCount() const { return buildCount_; }

  // One shadow ray per covered pixel toward a Point, Spot or Directional light (an area light is
  // treated as its centre). 1 lit, 0 shadowed, kNotFacing, kBackground.
  ImageF hardVisibility(const SurfaceBuffer& surface, const Light& light) const;
  // The visible fraction of an area light (Light::area Sphere or Rectangle, Point or Spot kind):
  // `samples` stratified rays per pixel, jittered per pixel from `seed` (deterministic, whatever
  // the thread count). Sphere: the fraction of the solid angle it subtends (uniform over its cone
  // of directions); Rectangle: the fraction of its area (centre position, edges size.x along
  // tangent and size.y along direction x tangent). Samples below the receiver's horizon count as
  // hidden. kNotFacing where N.L <= 0 toward the light's centre (as for hard shadows).
  // samples = sx * sy with sx the largest divisor <= sqrt(samples): square counts stratify best.
  ImageF softVisibility(const SurfaceBuffer& surface, const Light& areaLight, int samples, std::uint64_t seed) const;

  float rayEpsilon() const { return epsilon_; }
  std::size_t triangleCount() const { return triangles_; }
  double lastQueryMs() const { return lastQueryMs_; }  // wall time of the last visibility query
  double lastBuildMs() const { return lastBuildMs_; }

  // A single occlusion query from `origin` along unit `direction` up to `maxDistance` (no offset
  // applied): for tests and for lessons that probe one point.
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  TextureLookup textures_;
  GroundTruthOptions options_;
  float epsilon_ = 0.0f;
  std::size_t triangles_ = 0;
  std::uint64_t buildCount_ = 0;
  std::uint64_t revision_ = 0;
  bool hasRevision_ = false;
  mutable double lastQueryMs_ = 0.0;
  double lastBuildMs_ = 0.0;
};

}  // namespace shadowlab::measure

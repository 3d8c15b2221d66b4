#include "measure/ground_truth.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include <embree3/rtcore.h>

#include "core/parallel.hpp"

namespace shadowlab::measure {

namespace {

constexpr float kPi = 3.14159265358979323846f;

// What the filter function needs to find the alpha at a hit.
struct AlphaCard {
  std::vector<glm::vec2> uvs;          // per vertex
  std::vector<std::uint32_t> indices;  // three per triangle
  int width = 0, height = 0;
  std::vector<float> alpha;  // width * height, row 0 = v 0
  float cutoff = 0.5f;

  float sample(glm::vec2 uv) const {
    // Bilinear with repeat wrapping, texel centres at (i + 0.5) / size, as GL_LINEAR / GL_REPEAT.
    float fx = uv.x * width - 0.5f, fy = uv.y * height - 0.5f;
    float x0f = std::floor(fx), y0f = std::floor(fy);
    float tx = fx - x0f, ty = fy - y0f;
    auto wrap = [](long i, int n) {
      long r = i % n;
      return int(r < 0 ? r + n : r);
    };
    long x0 = long(x0f), y0 = long(y0f);
    int xa = wrap(x0, width), xb = wrap(x0 + 1, width);
    int ya = wrap(y0, height), yb = wrap(y0 + 1, height);
    auto at = [&](int x, int y) { return alpha[std::size_t(y) * width + x]; };
    float top = at(xa, ya) * (1 - tx) + at(xb, ya) * tx;
    float bottom = at(xa, yb) * (1 - tx) + at(xb, yb) * tx;
    return top * (1 - ty) + bottom * ty;
  }
};

void alphaFilter(const RTCFilterFunctionNArguments* args) {
  const auto* card = static_cast<const AlphaCard*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const std::uint32_t* tri = &card->indices[std::size_t(prim) * 3];
    glm::vec2 uv = (1.0f - u - v) * card->uvs[tri[0]] + u * card->uvs[tri[1]] + v * card->uvs[tri[2]];
    if (card->sample(uv) < card->cutoff) args->valid[i] = 0;  // a hole: keep tracing
  }
}

std::uint64_t splitmix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
float uniform01(std::uint64_t& state) { return float(splitmix(state) >> 40) * (1.0f / 16777216.0f); }

// Shirley-Chiu concentric map from the unit square to the unit disk: keeps strata compact.
glm::vec2 concentricDisk(float u, float v) {
  float a = 2 * u - 1, b = 2 * v - 1;
  if (a == 0 && b == 0) return {0, 0};
  float r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4) * (b / a);
  } else {
    r = b;
    phi = kPi / 2 - (kPi / 4) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  // Duff et al. 2017, branchless and continuous enough for sampling.
  float s = std::copysign(1.0f, n.z);
  float a = -1.0f / (s + n.z), c = n.x * n.y * a;
  t = {1 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

const char* kindName(LightKind k) {
  switch (k) {
    case LightKind::Point: return "Point";
    case LightKind::Spot: return "Spot";
    case LightKind::Directional: return "Directional";
  }
  return "unknown";
}

void checkLightKind(const Light& light, const char* where) {
  if (light.kind != LightKind::Point && light.kind != LightKind::Spot && light.kind != LightKind::Directional)
    throw std::invalid_argument(std::string(where) + ": unknown light kind " + std::to_string(int(light.kind)));
}

// The alpha card of mesh `index` with its material's texture (`image`: nullptr when the texture
// was not found): its uvs, triangles and alpha channel for the filter function. Throws for a
// missing or malformed texture or uvs that do not match the positions, naming them.
std::unique_ptr<AlphaCard> alphaCardOf(const Mesh& mesh, std::size_t index, const Material& material,
                                       const Image8* image) {
  if (!image)
    throw std::invalid_argument("GroundTruth: texture '" + material.texture + "' of alpha-tested material '" +
                                material.name + "' was not found");
  if (image->width <= 0 || image->height <= 0 || image->channels < 1 ||
      image->data.size() != std::size_t(image->width) * image->height * image->channels)
    throw std::invalid_argument("GroundTruth: texture '" + material.texture + "' is malformed (" +
                                std::to_string(image->width) + "x" + std::to_string(image->height) + "x" +
                                std::to_string(image->channels) + ")");
  if (mesh.uvs.size() != mesh.positions.size())
    throw std::invalid_argument("GroundTruth: alpha-tested mesh " + std::to_string(index) + " has " +
                                std::to_string(mesh.uvs.size()) + " uvs for " + std::to_string(mesh.positions.size()) +
                                " positions");
  auto card = std::make_unique<AlphaCard>();
  card->uvs = mesh.uvs;
  card->indices.assign(mesh.indices.begin(), mesh.indices.begin() + mesh.triangleCount() * 3);
  card->width = image->width;
  card->height = image->height;
  card->cutoff = material.alphaCutoff;
  int channel = image->channels == 4 ? 3 : image->channels == 2 ? 1 : 0;  // RGB: no alpha, use R
  card->alpha.resize(std::size_t(image->width) * image->height);
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x)
      card->alpha[std::size_t(y) * image->width + x] = image->at(x, y)[channel] / 255.0f;
  return card;
}

}  // namespace

struct GroundTruth::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaCard>> cards;

  Impl() {
    device = rtcNewDevice(nullptr);
    if (!device)
      throw std::runtime_error("GroundTruth: rtcNewDevice failed (error " +
                               std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  }
  ~Impl() {
    release();
    rtcReleaseDevice(device);
  }
  void release() {
    if (scene) rtcReleaseScene(scene);
    scene = nullptr;
    cards.clear();
  }
};

GroundTruth::GroundTruth(const Scene& scene, TextureLookup textures, GroundTruthOptions options)
    : impl_(std::make_unique<Impl>()), textures_(std::move(textures)), options_(options) {
  if (!(options_.relativeEpsilon > 0.0f))
    throw std::invalid_argument("GroundTruth: relativeEpsilon " + std::to_string(options_.relativeEpsilon) +
                                " must be > 0");
  rebuild(scene);
}

GroundTruth::GroundTruth(const Scene& scene, const std::map<std::string, Image8>& textures, GroundTruthOptions options)
    : GroundTruth(
          scene,
          [copy = std::make_shared<std::map<std::string, Image8>>(textures)](const std::string& name) -> const Image8* {
            auto it = copy->find(name);
            return it == copy->end() ? nullptr : &it->second;
          },
          options) {}

GroundTruth::~GroundTruth() = default;

void GroundTruth::rebuild(const Scene& scene) {
  auto start = std::chrono::steady_clock::now();
  // Built aside and swapped in on success: a throw leaves the previous BVH in place, and the guards
  // release what Embree allocated so far.
  struct SceneGuard {
    RTCScene scene;
    ~SceneGuard() {
      if (scene) rtcReleaseScene(scene);
    }
  } building{rtcNewScene(impl_->device)};
  struct GeometryGuard {
    RTCGeometry geometry;
    ~GeometryGuard() {
      if (geometry) rtcReleaseGeometry(geometry);
    }
  };
  std::vector<std::unique_ptr<AlphaCard>> cards;
  std::size_t triangles = 0;
  rtcSetSceneBuildQuality(building.scene, RTC_BUILD_QUALITY_HIGH);
  Aabb bounds;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    if (object.mesh >= scene.meshes.size())
      throw std::invalid_argument("GroundTruth: object '" + object.name + "' uses mesh " + std::to_string(object.mesh) +
                                  " of " + std::to_string(scene.meshes.size()));
    const Mesh& mesh = scene.meshes[object.mesh];
    // Bounds of every object, casters or not: eps follows the scene's scale.
    for (const glm::vec3& p : mesh.positions) bounds.extend(glm::vec3(object.model * glm::vec4(p, 1.0f)));
    if (!object.castsShadow || mesh.triangleCount() == 0) continue;
    for (std::uint32_t i : mesh.indices)
      if (i >= mesh.positions.size())
        throw std::invalid_argument("GroundTruth: mesh " + std::to_string(object.mesh) + " has index " +
                                    std::to_string(i) + " >= " + std::to_string(mesh.positions.size()) + " vertices");

    GeometryGuard guard{rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE)};
    RTCGeometry geom = guard.geometry;
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      glm::vec3 w(object.model * glm::vec4(mesh.positions[v], 1.0f));
      vertices[3 * v] = w.x;
      vertices[3 * v + 1] = w.y;
      vertices[3 * v + 2] = w.z;
    }
    auto* index = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(std::uint32_t), mesh.triangleCount()));
    std::copy(mesh.indices.begin(), mesh.indices.begin() + mesh.triangleCount() * 3, index);

    const Material* material = object.material < scene.materials.size() ? &scene.materials[object.material] : nullptr;
    if (material && material->alphaCutoff > 0.0f && !material->texture.empty()) {
      auto card = alphaCardOf(mesh, object.mesh, *material, textures_ ? textures_(material->texture) : nullptr);
      rtcSetGeometryUserData(geom, card.get());
      rtcSetGeometryIntersectFilterFunction(geom, alphaFilter);
      rtcSetGeometryOccludedFilterFunction(geom, alphaFilter);
      cards.push_back(std::move(card));
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(building.scene, geom);
    triangles += mesh.triangleCount();
  }
  rtcCommitScene(building.scene);
  if (RTCError err = rtcGetDeviceError(impl_->device); err != RTC_ERROR_NONE)
    throw std::runtime_error("GroundTruth: Embree error " + std::to_string(int(err)) + " while building");
  impl_->release();
  impl_->scene = building.scene;
  building.scene = nullptr;
  impl_->cards = std::move(cards);
  triangles_ = triangles;
  float diagonal = bounds.empty() ? 1.0f : glm::length(bounds.extent());
  epsilon_ = options_.relativeEpsilon * std::max(diagonal, 1e-6f);
  ++buildCount_;
  lastBuildMs_ = msSince(start);
}

bool GroundTruth::update(const Scene& scene, std::uint64_t revision) {
  if (hasRevision_ && revision == revision_) return false;
  rebuild(scene);
  revision_ = revision;
  hasRevision_ = true;
  return true;
}

namespace {
// A read-back pixel whose position or normal is not finite (a shader that wrote no surface: the
// benchmark's floor shader) is no surface to trace from: Embree aborts on such a ray.
bool finiteSurface(const SurfaceBuffer& surface, std::size_t i) {
  const glm::vec3 &p = surface.position[i], &n = surface.normal[i];
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(n.x) && std::isfinite(n.y) &&
         std::isfinite(n.z);
}

bool occludedRay(RTCScene scene, const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = o.x;
  ray.org_y = o.y;
  ray.org_z = o.z;
  ray.dir_x = d.x;
  ray.dir_y = d.y;
  ray.dir_z = d.z;
  ray.tnear = tnear;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  ray.time = 0.0f;
  rtcOccluded1(scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}
}  // namespace

bool GroundTruth::occluded(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const {
  return occludedRay(impl_->scene, origin, direction, 0.0f, maxDistance);
}

ImageF GroundTruth::hardVisibility(const SurfaceBuffer& surface, const Light& light) const {
  surface.validate();
  checkLightKind(light, "hardVisibility");
  auto start = std::chrono::steady_clock::now();
  ImageF out;
  out.width = surface.width;
  out.height = surface.height;
  out.channels = 1;
  out.data.assign(std::size_t(surface.width) * surface.height, kBackground);
  const float eps = epsilon_;
  const float cosOuter = std::cos(light.spotOuter);
  const glm::vec3 spotAxis = glm::normalize(light.direction);
  RTCScene scene = impl_->scene;
  parallelRows(surface.height, options_.threads, [&](int y) {
    for (int x = 0; x < surface.width; ++x) {
      std::size_t i = surface.index(x, y);
      if (!surface.covered[i] || !finiteSurface(surface, i)) continue;
      const glm::vec3 p = surface.position[i], n = surface.normal[i];
      glm::vec3 toLight;
      float distance;
      if (light.kind == LightKind::Directional) {
        toLight = -spotAxis;
        distance = std::numeric_limits<float>::infinity();
      } else {
        glm::vec3 d = light.position - p;
        distance = glm::length(d);
        toLight = distance > 0.0f ? d / distance : glm::vec3(0);
      }
      bool facing = glm::dot(n, toLight) > 0.0f;
      if (facing && light.kind == LightKind::Spot && glm::dot(-toLight, spotAxis) < cosOuter) facing = false;
      if (!facing) {
        out.data[i] = kNotFacing;
        continue;
      }
      glm::vec3 origin = p + eps * n;
      float tfar = light.kind == LightKind::Directional ? distance : glm::length(light.position - origin) - eps;
      glm::vec3 dir = light.kind == LightKind::Directional ? toLight : glm::normalize(light.position - origin);
      out.data[i] = (tfar > 0.0f && occludedRay(scene, origin, dir, 0.0f, tfar)) ? 0.0f : 1.0f;
    }
  });
  lastQueryMs_ = msSince(start);
  return out;
}

namespace {

// Throws for a light softVisibility cannot sample, naming why.
void checkSoftLight(const Light& light, int samples) {
  checkLightKind(light, "softVisibility");
  if (samples <= 0) throw std::invalid_argument("softVisibility: samples " + std::to_string(samples) + " must be > 0");
  if (light.kind == LightKind::Directional)
    throw std::invalid_argument(
        "softVisibility: light kind Directional has no area (use Point or Spot with an area shape)");
  if (light.area != AreaShape::Sphere && light.area != AreaShape::Rectangle)
    throw std::invalid_argument("softVisibility: area shape " + std::to_string(int(light.area)) +
                                " is not Sphere or Rectangle (light kind " + kindName(light.kind) + ")");
  if (light.area == AreaShape::Sphere && !(light.radius > 0.0f))
    throw std::invalid_argument("softVisibility: sphere radius " + std::to_string(light.radius) + " must be > 0");
  if (light.area == AreaShape::Rectangle && !(light.size.x > 0.0f && light.size.y > 0.0f))
    throw std::invalid_argument("softVisibility: rectangle size " + std::to_string(light.size.x) + "x" +
                                std::to_string(light.size.y) + " must be positive");
}

// Shadow rays from one surface point toward the light's area. A sphere: uniform directions in the
// cone it subtends (a point inside it sees it all around); a rectangle: uniform points on it.
struct AreaSampler {
  const Light& light;
  glm::vec3 origin, axis, rectU, rectV;
  float cosMax = -1.0f;
  glm::vec3 t{0.0f}, b{0.0f};

  // The ray's direction and length (to the emitter's near surface) for (u, v) in [0, 1)^2.
  void sample(float u, float v, glm::vec3& dir, float& tfar) const {
    if (light.area == AreaShape::Sphere) {
      if (cosMax <= -1.0f) {  // inside the emitter: the whole sphere of directions
        float z = 1 - 2 * u, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPi * v;
        dir = {r * std::cos(phi), r * std::sin(phi), z};
        tfar = light.radius;  // conservative: stays inside the emitter
      } else {
        glm::vec2 d = concentricDisk(u, v);
        float r2 = glm::dot(d, d);
        float cosT = 1.0f - r2 * (1.0f - cosMax);
        float sinT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT));
        float scale = r2 > 0.0f ? sinT / std::sqrt(r2) : 0.0f;
        dir = glm::normalize(cosT * axis + scale * (d.x * t + d.y * b));
        // Distance to the sphere's near surface along dir (the ray must stop before the emitter).
        glm::vec3 oc = origin - light.position;
        float bq = glm::dot(oc, dir), cq = glm::dot(oc, oc) - light.radius * light.radius;
        float disc = bq * bq - cq;
        tfar = disc > 0.0f ? -bq - std::sqrt(disc) : -bq;
      }
    } else {
      glm::vec3 q = light.position + (u - 0.5f) * light.size.x * rectU + (v - 0.5f) * light.size.y * rectV;
      glm::vec3 d = q - origin;
      float len = glm::length(d);
      dir = len > 0.0f ? d / len : axis;
      tfar = len;
    }
  }
};

// Occlusion rays to Embree 16 at a time from one origin (one packet shares origin and context):
// about twice the throughput of single rays here. `visible` counts the rays that reached the light.
struct OcclusionPacket16 {
  alignas(64) RTCRay16 packet;
  alignas(64) int valid[16];
  int queued = 0;
  int visible = 0;

  void setLane(int q, const glm::vec3& origin, const glm::vec3& dir, float tfar, unsigned mask) {
    packet.org_x[q] = origin.x;
    packet.org_y[q] = origin.y;
    packet.org_z[q] = origin.z;
    packet.dir_x[q] = dir.x;
    packet.dir_y[q] = dir.y;
    packet.dir_z[q] = dir.z;
    packet.tnear[q] = 0.0f;
    packet.tfar[q] = tfar;
    packet.time[q] = 0.0f;
    packet.mask[q] = mask;
    packet.id[q] = 0;
    packet.flags[q] = 0;
  }
  void push(RTCScene scene, const glm::vec3& origin, const glm::vec3& dir, float tfar, const glm::vec3& n) {
    setLane(queued, origin, dir, tfar, 0xFFFFFFFFu);
    valid[queued] = -1;
    if (++queued == 16) flush(scene, origin, n);
  }
  void flush(RTCScene scene, const glm::vec3& origin, const glm::vec3& n) {
    // The lanes left out still hold finite rays: Embree's AVX2 kernels (two 8-wide halves of
    // the packet) assert on ray.valid() over lanes that were never written, an abort that came
    // and went with whatever the stack held (measure.ground_truth's 1x1 view, 4 samples).
    for (int q = queued; q < 16; ++q) {
      valid[q] = 0;
      setLane(q, origin, n, 0.0f, 0u);
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded16(valid, scene, &context, &packet);
    for (int q = 0; q < queued; ++q) visible += packet.tfar[q] >= 0.0f;
    queued = 0;
  }
};

}  // namespace

ImageF GroundTruth::softVisibility(const SurfaceBuffer& surface, const Light& light, int samples,
                                   std::uint64_t seed) const {
  surface.validate();
  checkSoftLight(light, samples);
  auto start = std::chrono::steady_clock::now();
  int sx = 1;
  for (int d = 1; d * d <= samples; ++d)
    if (samples % d == 0) sx = d;
  const int sy = samples / sx;

  ImageF out;
  out.width = surface.width;
  out.height = surface.height;
  out.channels = 1;
  out.data.assign(std::size_t(surface.width) * surface.height, kBackground);
  const float eps = epsilon_;
  const float cosOuter = std::cos(light.spotOuter);
  const glm::vec3 spotAxis = glm::normalize(light.direction);
  const glm::vec3 rectU = glm::normalize(light.tangent);
  const glm::vec3 rectV = glm::normalize(glm::cross(spotAxis, rectU));
  RTCScene scene = impl_->scene;

  parallelRows(surface.height, options_.threads, [&](int y) {
    for (int x = 0; x < surface.width; ++x) {
      std::size_t i = surface.index(x, y);
      if (!surface.covered[i] || !finiteSurface(surface, i)) continue;
      const glm::vec3 p = surface.position[i], n = surface.normal[i];
      glm::vec3 toCentre = light.position - p;
      float centreDistance = glm::length(toCentre);
      glm::vec3 axis = centreDistance > 0.0f ? toCentre / centreDistance : glm::vec3(0);
      bool facing = glm::dot(n, axis) > 0.0f;
      if (facing && light.kind == LightKind::Spot && glm::dot(-axis, spotAxis) < cosOuter) facing = false;
      if (!facing) {
        out.data[i] = kNotFacing;
        continue;
      }
      AreaSampler area{light, p + eps * n, axis, rectU, rectV};
      if (light.area == AreaShape::Sphere) {
        float s = light.radius / centreDistance;
        area.cosMax = s < 1.0f ? std::sqrt(std::max(0.0f, 1.0f - s * s)) : -1.0f;
        orthonormalBasis(axis, area.t, area.b);
      }
      std::uint64_t state = seed ^ (std::uint64_t(i) * 0xD1B54A32D192ED03ull);
      splitmix(state);
      OcclusionPacket16 rays;
      for (int j = 0; j < sy; ++j)
        for (int k = 0; k < sx; ++k) {
          float u = (k + uniform01(state)) / sx, v = (j + uniform01(state)) / sy;
          glm::vec3 dir;
          float tfar;
          area.sample(u, v, dir, tfar);
          tfar -= eps;
          if (glm::dot(dir, n) <= 0.0f || tfar <= 0.0f) continue;  // below the horizon: hidden
          rays.push(scene, area.origin, dir, tfar, n);
        }
      if (rays.queued) rays.flush(scene, area.origin, n);
      out.data[i] = float(rays.visible) / float(samples);
    }
  });
  lastQueryMs_ = msSince(start);
  return out;
}

}  // namespace shadowlab::measure

// Lesson 03: shadow-map quality (seeds 000 §2, 002, 004). Everything that makes lesson 02's maps
// good, each a switch:
//   bias      constant, slope-scaled (polygon offset and in the shader), normal offset, receiver
//             plane, front-face culling in the depth pass
//   texels    resolution 256..8192; filtering nearest, hardware 2x2 PCF, N x N PCF, Poisson disk
//   fitting   a directional light whose orthographic frustum covers only the receivers the view
//             needs and the casters that can shade them (the light volume swept from the view
//             frustum toward the light); casters outside are not drawn; texel snapping
//   lights    a point light with a cube map (faces the view cannot see are skipped), a spot light,
//             all at once, each with its own map
//
// Controls: left drag orbit, right drag pan, wheel zoom; P cycles the filter, B front-face culling,
// N normal offset, R receiver plane, S snapping, K caster culling, D camera drift, 1 2 3 the
// lights, V the view, M the ground-truth overlays, O the god view; F1 help.
// Exercises (exercises.hpp): slope-scaled bias, PCF weights, cube face selection, the caster
// culling test, the orthographic fit.
#include <glm/gtc/matrix_transform.hpp>

#include "app/lesson.hpp"
#include "core/scene_gen.hpp"
#include "algorithms/shadow_math.hpp"
#include "exercises.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/scene_draw.hpp"
#include "gl/shadow_map.hpp"

using namespace shadowlab;

namespace {

enum class Filter { Nearest, Hardware2x2, BoxNxN, Poisson };
enum class Fit { Scene, View };
enum class View { Lit, Visibility, SunMap };
enum class Impl { Reference, Student };
const std::vector<std::string> kSizes{"256", "512", "1024", "2048", "4096", "8192"};
constexpr int kSun = 0, kPoint = 1, kSpot = 2;

struct Params {
  int scene = 1;          // city: long straight edges show acne, aliasing and shimmer
  int triangles = 60000;  // every shadow pass draws what survives culling
  int mapSize = 3;        // 2048^2 (index into kSizes), the sun's and the spot's maps
  int cubeSize = 2;       // 1024^2 per cube face
  gl::DepthFormat format = gl::DepthFormat::Depth24;
  Filter filter = Filter::Hardware2x2;  // GL_LINEAR on a comparison sampler: free 2x2 PCF
  int pcfSize = 3;                      // N of N x N PCF (odd)
  float poissonRadius = 2.0f;           // Poisson disk radius in texels
  float constantBias = 0.0005f;         // depth units subtracted before the comparison
  float slopeBias = 0.0005f;            // times tan(theta): steep receivers need more
  float maxBias = 0.003f;               // clamp: tan(theta) grows without bound at grazing light
  float offsetFactor = 1.0f;            // glPolygonOffset factor (slope-scaled, in the depth pass)
  float offsetUnits = 1.0f;             // glPolygonOffset units (constant, in format steps)
  float normalOffset = 0.5f;            // lookup point moved this many texels along the normal
  bool receiverPlane = false;           // filter taps compare against the receiver's plane
  bool cullFront = false;               // depth pass draws back faces: the bias is the object's thickness
  Fit fit = Fit::View;                  // sun frustum around the whole scene, or only what the view needs
  bool snap = true;                     // texel snapping: no shimmer when the camera moves
  bool cullCasters = true;              // skip casters outside the swept light volume / light frusta
  bool skipFaces = true;                // skip cube faces the view frustum misses
  float pointNear = 0.2f, pointFar = 60.0f;
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your culling test and fit drive the sun's pass
  bool drift = false;           // move the camera slowly (shows shimmer without snapping)
  float ambient = 0.1f;
  Light lights[3];
};

struct Pass {  // one light camera: what it draws and into which map
  glm::mat4 viewProj{1.0f};
  shadow::ConvexVolume volume;
};

}  // namespace

class ShadowQualityLesson : public Lesson {
 public:
  LessonInfo info() const override {
    return {"03",
            "03_shadow_quality",
            "Shadow-map quality",
            "Bias family, resolution, PCF family, a directional light fitted to the view with caster culling and texel "
            "snapping, cube maps, several lights.",
            3,
            "Bias: bias.* sliders, B front-face culling, N normal offset, R receiver plane.\n"
            "Filtering: P cycles nearest, hardware 2x2, N x N, Poisson. map_size 256..8192.\n"
            "Fit: fit=scene vs view; K caster culling (culled casters in the header); S snapping\n"
            "with D (camera drift): shimmer without it. 1 2 3: sun, point (cube map), spot.\n"
            "M: error and aliasing heatmaps against ground truth; O: god view with the light frusta.",
            true};
  }

  void declare(ParamRegistry& r) override {
    camera.target = {0, 2, 0};
    camera.distance = 45.0f;
    camera.pitch = 0.5f;
    r.addChoice("scene", &p_.scene, sceneNames(), "procedural scene");
    r.add("triangles", &p_.triangles, 10000, 1000000, "scene size: what the shadow passes draw");
    r.addChoice("map_size", &p_.mapSize, kSizes, "sun and spot map resolution (texels per side)");
    r.addChoice("cube_size", &p_.cubeSize, kSizes, "point light cube-map face resolution");
    r.addChoice("format", &p_.format, {"16", "24", "32f"}, "depth format of every map");
    r.addChoice("filter", &p_.filter, {"nearest", "hardware_2x2", "pcf_nxn", "poisson"},
                "one comparison, GL_LINEAR compare (2x2), N x N taps, or 16 rotated Poisson taps")
        .hotkey = "P";
    r.add("pcf.size", &p_.pcfSize, 1, 9, "N of the N x N kernel (odd)");
    r.add("pcf.radius", &p_.poissonRadius, 0.5f, 8, "Poisson disk radius in texels");
    r.add("bias.constant", &p_.constantBias, 0, 0.1f, "constant depth bias in the shader");
    r.add("bias.slope", &p_.slopeBias, 0, 0.02f, "slope-scaled bias in the shader: times tan(theta)");
    r.add("bias.max", &p_.maxBias, 0, 0.1f, "upper clamp of the in-shader bias");
    r.add("offset.factor", &p_.offsetFactor, 0, 10, "glPolygonOffset factor: slope-scaled, in the depth pass");
    r.add("offset.units", &p_.offsetUnits, 0, 100, "glPolygonOffset units: constant, in depth-format steps");
    r.add("bias.normal_offset", &p_.normalOffset, 0, 4, "look up from a point this many texels along the normal")
        .hotkey = "N";
    r.add("bias.receiver_plane", &p_.receiverPlane, "filter taps follow the receiver's plane (no PCF acne)").hotkey =
        "R";
    r.add("cull_front", &p_.cullFront, "depth pass draws back faces only: closed casters need no bias").hotkey = "B";
    r.addChoice("fit", &p_.fit, {"scene", "view"}, "sun frustum: around the scene, or fitted to the receivers in view")
        .hotkey = "F";
    r.add("snap", &p_.snap, "texel snapping of the fitted frustum (no shimmer)").hotkey = "S";
    r.add("cull_casters", &p_.cullCasters, "skip casters that cannot shade anything in view").hotkey = "K";
    r.add("skip_faces", &p_.skipFaces, "skip cube faces whose frustum misses the view frustum");
    r.add("point.near", &p_.pointNear, 0.01f, 10, "cube faces' near plane");
    r.add("point.far", &p_.pointFar, 1, 500, "cube faces' far plane: beyond it, lit");
    r.addChoice("view", &p_.view, {"lit", "visibility", "sun_map"}, "lit, V of the measured light, or the sun's map")
        .hotkey = "V";
    r.addChoice("impl", &p_.impl, {"reference", "student"},
                "whose caster-culling test and orthographic fit drive the sun's pass");
    r.add("drift", &p_.drift, "move the camera slowly along x (watch edges shimmer without snapping)").hotkey = "D";
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    Light* l = p_.lights;
    l[kSun] = {LightKind::Directional};
    l[kSun].direction = glm::normalize(glm::vec3(-0.45f, -1.0f, -0.3f));
    l[kSun].color = {1.0f, 0.95f, 0.85f};
    l[kSun].intensity = 0.9f;
    l[kPoint] = {LightKind::Point, {4.0f, 6.0f, 3.0f}};
    l[kPoint].color = {1.0f, 0.6f, 0.3f};
    l[kPoint].intensity = 3.0f;
    l[kPoint].attenuation = {1.0f, 0.05f, 0.02f};
    l[kPoint].enabled = false;
    l[kSpot] = {LightKind::Spot, {-12.0f, 16.0f, 10.0f}};
    l[kSpot].direction = glm::normalize(glm::vec3(12.0f, -16.0f, -10.0f));
    l[kSpot].color = {0.5f, 0.7f, 1.0f};
    l[kSpot].intensity = 2.0f;
    l[kSpot].attenuation = {1.0f, 0.0f, 0.002f};
    l[kSpot].spotInner = 0.35f;
    l[kSpot].spotOuter = 0.5f;
    l[kSpot].enabled = false;
    const char* names[3] = {"sun.", "point.", "spot."};
    for (int i = 0; i < 3; ++i) {
      const std::string n = names[i];
      r.add(n + "enabled", &l[i].enabled, "switch this light (and its map) on or off").hotkey = std::to_string(i + 1);
      if (i != kSun) r.add(n + "position", &l[i].position, -100, 100, "where the light is");
      if (i != kPoint)
        r.add(n + "direction", &l[i].direction, -1, 1,
              i == kSun ? "the direction sunlight travels" : "the spot's axis");
      r.add(n + "intensity", &l[i].intensity, 0, 20, "the light's strength");
    }
  }

  void init() override {
    depthProgram_.build();
    sceneProgram_.build();
    mapView_.build();
    compareNearest_ = gl::makeCompareSampler(false, "03 compare nearest");
    compareLinear_ = gl::makeCompareSampler(true, "03 compare linear (2x2 PCF)");
    rawDepth_ = gl::makeRawDepthSampler("03 raw depth");
    emptyVao_ = gl::makeVertexArray("03 fullscreen");
    loadScene();
  }

  MeasureSource measureSource() override {
    return {&scene_, std::uint64_t(builtScene_ * 10000000 + builtTriangles_), {p_.lights, p_.lights + 3}};
  }

  void update(const FrameInfo& f) override {
    if (p_.scene != builtScene_ || p_.triangles != builtTriangles_) loadScene();
    const int size = std::stoi(kSizes[std::size_t(p_.mapSize)]), cube = std::stoi(kSizes[std::size_t(p_.cubeSize)]);
    if (sun_.size != size || sun_.format != p_.format) sun_ = gl::makeShadowMap(size, p_.format, "03 sun map");
    if (spot_.size != size || spot_.format != p_.format) spot_ = gl::makeShadowMap(size, p_.format, "03 spot map");
    if (point_.size != cube || point_.format != p_.format)
      point_ = gl::makeShadowCube(cube, p_.format, "03 point cube map");
    if (p_.drift) camera.target.x += float(f.dt) * 0.37f;
    if (p_.pcfSize % 2 == 0) p_.pcfSize += 1;
  }

  void render(const FrameInfo& f) override {
    const bool student = p_.impl == Impl::Student;
    const float aspect = float(f.width) / float(std::max(f.height, 1));
    // The viewer's frustum (never the god view's): what the shadows must serve.
    const shadow::ConvexVolume viewVolume = shadow::volumeFromViewProj(camera.projection(aspect) * camera.view());

    // ==== 1. the sun: fit the orthographic frustum, cull casters against the swept volume ========
    const glm::vec3 sunDir = glm::normalize(p_.lights[kSun].direction);
    std::vector<char> sunCasters(scene_.objects.size(), 1);
    std::vector<Aabb> keptBoxes;
    int culled = 0;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      if (!scene_.objects[i].castsShadow) {
        sunCasters[i] = 0;
        continue;
      }
      const bool keep = !p_.cullCasters || (student ? ex03::casterMayShadow(boxes_[i], viewVolume, sunDir)
                                                    : shadow::casterMayShadow(boxes_[i], viewVolume, sunDir));
      sunCasters[i] = keep;
      if (keep) keptBoxes.push_back(boxes_[i]);
      else if (p_.lights[kSun].enabled) ++culled;
    }
    std::vector<glm::vec3> receivers;
    const shadow::ConvexVolume sceneVolume = shadow::volumeFromBox(sceneBounds_);
    if (p_.fit == Fit::View) receivers = shadow::intersectionPoints(sceneVolume, viewVolume);
    if (receivers.empty()) receivers.assign(sceneVolume.corners.begin(), sceneVolume.corners.end());
    const std::span<const Aabb> fitCasters =
        p_.fit == Fit::View ? std::span<const Aabb>(keptBoxes) : std::span<const Aabb>();
    const bool snap = p_.snap && p_.fit == Fit::View;
    const shadow::OrthoFit fit = student ? ex03::fitOrthographic(sunDir, receivers, fitCasters, sun_.size, snap)
                                         : shadow::fitOrthographic(sunDir, receivers, fitCasters, sun_.size, snap);
    const glm::mat4 sunViewProj = fit.projection * fit.view;
    const Light& spot = p_.lights[kSpot];
    const float spotFov = std::min(2.0f * spot.spotOuter + 0.05f, 3.0f);
    const glm::mat4 spotViewProj =
        glm::perspective(spotFov, 1.0f, 0.5f, 150.0f) * shadow::lightViewAlong(spot.position, spot.direction);
    const glm::mat4 cubeProj =
        glm::perspective(glm::radians(90.0f), 1.0f, p_.pointNear, std::max(p_.pointFar, p_.pointNear + 0.1f));

    // ==== 2. shadow passes: sun, spot (one 2D map each), point (six cube faces) =================
    if (!f.godView) {
      std::size_t triangles = 0;
      int skipped = 0;
      glEnable(GL_DEPTH_TEST);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(p_.offsetFactor, p_.offsetUnits);
      depthProgram_.use();
      depthProgram_.set("uAlphaTest", true);
      depthProgram_.set("uTexture", 0);
      if (p_.lights[kSun].enabled) {
        auto t = scope("shadow sun");
        gl::beginShadowPass(sun_);
        triangles += drawCasters(sunViewProj, sunCasters);
      }
      if (spot.enabled) {
        auto t = scope("shadow spot");
        gl::beginShadowPass(spot_);
        triangles += drawCasters(spotViewProj, cullAgainst(shadow::volumeFromViewProj(spotViewProj), culled));
      }
      if (p_.lights[kPoint].enabled) {
        auto t = scope("shadow point");
        for (int face = 0; face < 6; ++face) {
          const glm::mat4 vp = cubeProj * shadow::cubeFaceView(p_.lights[kPoint].position, face);
          const shadow::ConvexVolume faceVolume = shadow::volumeFromViewProj(vp);
          gl::beginShadowPass(point_, face);  // a skipped face is cleared: lit, never stale
          if (p_.skipFaces && !shadow::volumesMayIntersect(faceVolume, viewVolume)) {
            ++skipped;
            continue;
          }
          triangles += drawCasters(vp, cullAgainst(faceVolume, culled));
        }
      }
      glDisable(GL_POLYGON_OFFSET_FILL);
      glCullFace(GL_BACK);
      glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer);
      glViewport(0, 0, f.width, f.height);
      stats_ = {triangles, culled, skipped};
    }
    // Texels drawn into this frame: the sun's and spot's maps, and the cube faces not skipped.
    const std::uint64_t mapSide = std::stoull(kSizes[std::size_t(p_.mapSize)]),
                        cubeSide = std::stoull(kSizes[std::size_t(p_.cubeSize)]);
    const std::uint64_t texels =
        std::uint64_t(p_.lights[kSun].enabled + spot.enabled) * mapSide * mapSide +
        (p_.lights[kPoint].enabled ? std::uint64_t(6 - stats_.skipped) * cubeSide * cubeSide : 0);
    counters = {{"shadow triangles", std::to_string(stats_.triangles)},
                {"shadow texels", std::to_string(texels)},
                {"culled casters", std::to_string(stats_.culled)},
                {"cube faces skipped", std::to_string(stats_.skipped)},
                {"sun texel", std::to_string(fit.texelWorld * 100.0f).substr(0, 5) + " cm"}};
    debug.frustum(sunViewProj, {1.0f, 0.9f, 0.3f, 1.0f});
    if (spot.enabled) debug.frustum(spotViewProj, {0.5f, 0.7f, 1.0f, 1.0f});
    if (p_.lights[kPoint].enabled) debug.cross(p_.lights[kPoint].position, 0.5f, {1.0f, 0.6f, 0.3f, 1.0f});
    if (p_.fit == Fit::View) debug.box(sceneBounds_, {0.4f, 0.4f, 0.4f, 1.0f});

    // ==== 3. the scene from the eye, every light with its map =====================================
    {
      auto t = scope("scene");
      glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      drawScene(f, shadow::textureMatrix(fit.projection, fit.view),
                shadow::textureMatrix(glm::mat4(1.0f), spotViewProj), fit.texelWorld,
                2.0f * std::tan(0.5f * spotFov) / float(spot_.size));
    }

    // ==== 4. the sun's map as an image (view=sun_map) ==============================================
    if (p_.view == View::SunMap) {
      auto t = scope("map view");
      const int side = std::min(f.width, f.height);
      glViewport((f.width - side) / 2, 0, side, side);
      glClear(GL_DEPTH_BUFFER_BIT);
      mapView_.use();
      mapView_.set("uDepth", 4);
      mapView_.set("uPerspective", false);
      glActiveTexture(GL_TEXTURE4);
      glBindTexture(GL_TEXTURE_2D, sun_.texture.id());
      glBindSampler(4, rawDepth_.id());
      glBindVertexArray(emptyVao_.id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glBindSampler(4, 0);
      glActiveTexture(GL_TEXTURE0);
      glViewport(0, 0, f.width, f.height);
    }
  }

 private:
  void loadScene() {
    scene_ = makeScene(sceneNames()[std::size_t(p_.scene)], 1, std::size_t(p_.triangles));
    gpu_ = gl::uploadScene(scene_, "03 scene");
    boxes_.clear();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) boxes_.push_back(scene_.objectBounds(i));
    sceneBounds_ = scene_.bounds();
    builtScene_ = p_.scene;
    builtTriangles_ = p_.triangles;
  }

  // Casters whose box can meet a light frustum (spot, cube face): the others are not drawn.
  std::vector<char> cullAgainst(const shadow::ConvexVolume& lightVolume, int& culled) {
    std::vector<char> keep(scene_.objects.size(), 1);
    for (std::size_t i = 0; i < keep.size(); ++i) {
      if (!scene_.objects[i].castsShadow) {
        keep[i] = 0;
        continue;
      }
      keep[i] = !p_.cullCasters || shadow::volumesMayIntersect(shadow::volumeFromBox(boxes_[i]), lightVolume);
      if (!keep[i]) ++culled;  // counted per light camera: a caster can be culled from several
    }
    return keep;
  }

  std::size_t drawCasters(const glm::mat4& viewProj, const std::vector<char>& keep) {
    depthProgram_.set("uLightViewProj", viewProj);
    glEnable(GL_CULL_FACE);
    glCullFace(p_.cullFront ? GL_FRONT : GL_BACK);
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      if (!keep[i]) continue;
      const SceneObject& o = scene_.objects[i];
      const Material& m = scene_.materials[o.material];
      const GLuint tex = gpu_.materialTextures[o.material].id();
      depthProgram_.set("uModel", o.model);
      depthProgram_.set("uAlphaCutoff", m.alphaCutoff);
      depthProgram_.set("uUseTexture", tex != 0);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, tex);
      m.twoSided ? glDisable(GL_CULL_FACE) : glEnable(GL_CULL_FACE);
      gpu_.meshes[o.mesh].draw();
      triangles += scene_.meshes[o.mesh].triangleCount();
    }
    return triangles;
  }

  void drawScene(const FrameInfo& f, const glm::mat4& sunMatrix, const glm::mat4& spotMatrix, float sunTexel,
                 float spotTexelAngle) {
    gl::Program& s = sceneProgram_;
    s.use();
    s.set("uViewProj", f.projection * f.view);
    s.set("uEye", f.eye);
    s.set("uAmbient", glm::vec3(p_.ambient));
    s.set("uSunMatrix", sunMatrix);
    s.set("uSpotMatrix", spotMatrix);
    s.set("uSunTexelWorld", sunTexel);
    s.set("uSpotTexelAngle", spotTexelAngle);
    s.set("uPointNear", p_.pointNear);
    s.set("uPointFar", std::max(p_.pointFar, p_.pointNear + 0.1f));
    s.set("uMapSize", float(sun_.size));
    s.set("uCubeSize", float(point_.size));
    s.set("uFilter", int(p_.filter));
    s.set("uPcfSize", p_.pcfSize);
    s.set("uPoissonRadius", p_.poissonRadius);
    s.set("uConstantBias", p_.constantBias);
    s.set("uSlopeBias", p_.slopeBias);
    s.set("uMaxBias", p_.maxBias);
    s.set("uNormalOffset", p_.normalOffset);
    s.set("uReceiverPlane", p_.receiverPlane);
    s.set("uView", int(p_.view == View::Visibility));
    s.set("uMeasureLight", f.measureLight);
    s.set("uTexture", 0);
    s.set("uSunMap", 1);
    s.set("uSpotMap", 2);
    s.set("uPointMap", 3);
    for (int i = 0; i < 3; ++i) {
      const Light& l = p_.lights[i];
      const std::string n = "uLights[" + std::to_string(i) + "].";
      s.set((n + "kind").c_str(), int(l.kind));
      s.set((n + "enabled").c_str(), l.enabled);
      s.set((n + "position").c_str(), l.position);
      s.set((n + "direction").c_str(), glm::normalize(l.direction));
      s.set((n + "color").c_str(), l.color * l.intensity);
      s.set((n + "attenuation").c_str(), l.attenuation);
      s.set((n + "cosInner").c_str(), std::cos(l.spotInner));
      s.set((n + "cosOuter").c_str(), std::cos(l.spotOuter));
    }
    const GLuint sampler =
        p_.filter == Filter::Nearest || p_.filter == Filter::BoxNxN ? compareNearest_.id() : compareLinear_.id();
    const std::pair<GLenum, GLuint> maps[3] = {{GL_TEXTURE_2D, sun_.texture.id()},
                                               {GL_TEXTURE_2D, spot_.texture.id()},
                                               {GL_TEXTURE_CUBE_MAP, point_.texture.id()}};
    for (int u = 0; u < 3; ++u) {
      glActiveTexture(GLenum(GL_TEXTURE1 + u));
      glBindTexture(maps[u].first, maps[u].second);
      glBindSampler(GLuint(1 + u), sampler);
    }
    gl::drawScene(s, scene_, gpu_);
    for (int u = 1; u <= 3; ++u) glBindSampler(GLuint(u), 0);
    glActiveTexture(GL_TEXTURE0);
  }

  Params p_;
  Scene scene_;
  gl::GpuScene gpu_;
  std::vector<Aabb> boxes_;  // world bounds of every object: the culling tests' input
  Aabb sceneBounds_;
  gl::ShadowMap sun_, spot_, point_;
  gl::Sampler compareNearest_, compareLinear_, rawDepth_;
  gl::VertexArray emptyVao_;
  gl::Program depthProgram_{"03 depth", {"02_shadow_maps/depth.vert", "02_shadow_maps/depth.frag"}};
  gl::Program sceneProgram_{"03 scene", {"03_shadow_quality/scene.vert", "03_shadow_quality/scene.frag"}};
  gl::Program mapView_{"03 map view", {"common/fullscreen.vert", "02_shadow_maps/depth_view.frag"}};
  struct {
    std::size_t triangles = 0;
    int culled = 0, skipped = 0;
  } stats_;
  int builtScene_ = -1, builtTriangles_ = -1;
};

int main(int argc, char** argv) { return runLesson<ShadowQualityLesson>(argc, argv); }

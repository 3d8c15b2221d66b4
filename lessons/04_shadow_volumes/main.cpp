// Lesson 04: stencil shadow volumes, done right. The lecture's passes (seeds 004, shadow volumes)
// made robust after Everitt and Kilgard, "Practical and Robust Stenciled Shadow Volumes" (2002):
//   1. depth and ambient        the scene once: depth, ka Ia, and V = 0 for the measurement
//   per light (scissored to its reach):
//   2. stencil counting         the volumes: silhouette quads to infinity (w = 0), caps for z-fail;
//                               z-pass or z-fail per object (z-fail only if its volume can reach
//                               the near plane); two-sided stencil in one pass, or two passes
//   3. lit pass                 the scene again, adding the light where the count is 0
// Silhouettes come from an edge adjacency built once per mesh, on the CPU or in a geometry shader
// (triangles_adjacency). An infinite far plane (or GL_DEPTH_CLAMP) keeps the far caps unclipped.
// Open meshes are found when the adjacency is built and skipped or drawn z-pass only, on screen.
//
// Controls: orbit/pan/zoom with the mouse; V cycles the view (lit, volumes, wireframe, stencil
// heatmap, silhouettes), Z the method (auto, z-pass, z-fail), S CPU/GPU silhouettes, T two-sided
// stencil, A animates the point light, M the ground-truth error overlay; F1 help.
// Exercises (exercises.hpp): silhouettes, the infinite projection, the stencil ops, the near-plane
// test. `--set impl=student` runs YOUR versions in the lesson.
#include <algorithm>
#include <cmath>

#include "app/lesson.hpp"
#include "algorithms/lighting.hpp"
#include "core/scene_gen.hpp"
#include "algorithms/shadow_volume.hpp"
#include "exercises.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/scene_draw.hpp"

using namespace shadowlab;

namespace {

enum class View { Lit, Volumes, Wireframe, Stencil, Silhouettes };
enum class Method { Auto, ZPass, ZFail };
enum class Silhouettes { Cpu, Gpu };
enum class FarPlane { Infinite, DepthClamp };
enum class OpenMeshes { Skip, ZPassOnly };
enum class Impl { Reference, Student };

struct Params {
  int scene = 0;                               // showcase: closed shapes on an open ground plane
  int triangles = 40000;                       // more triangles: more silhouette edges, more fill
  View view = View::Lit;                       // the inner buffers: volumes, stencil counts, silhouettes
  int viewLight = 0;                           // whose volumes / stencil the views show
  Method method = Method::Auto;                // auto: z-fail only where z-pass can fail
  Silhouettes silhouettes = Silhouettes::Cpu;  // CPU (cached per light) or geometry shader (every frame)
  bool twoSided = true;                        // glStencilOpSeparate: both faces in one pass
  FarPlane far = FarPlane::Infinite;           // how the points at infinity escape the far clip plane
  OpenMeshes openMeshes = OpenMeshes::Skip;    // an open mesh's volume has holes: skip or z-pass only
  bool scissor = true;                         // each light touches only the pixels within its reach
  bool fillQuery = true;                       // count every volume fragment (occlusion query), in its own pass
  Impl impl = Impl::Reference;                 // student: your exercises.cpp drives the lesson
  float ambient = 0.08f;
  float specular = 0.35f;
  float shininess = 48.0f;
  bool animate = false;  // orbit the point light: the volumes are rebuilt every frame
  Light lights[4];
};
constexpr int kLights = 4;

GLenum toGl(volume::StencilOp op) {
  return op == volume::StencilOp::IncrWrap ? GL_INCR_WRAP : op == volume::StencilOp::DecrWrap ? GL_DECR_WRAP : GL_KEEP;
}

// One light's volumes for every caster (algorithms/shadow_volume: per object sides, then caps), built on
// the CPU and kept on the GPU until the light, the scene or the implementation changes.
struct VolumeCache : volume::SceneVolumes {
  glm::vec4 light{0.0f};
  int built = -1;  // scene revision it was built for
  gl::Buffer buffer;
  gl::VertexArray vao;
};

}  // namespace

class ShadowVolumeLesson : public Lesson {
 public:
  LessonInfo info() const override {
    return {
        "04",
        "04_shadow_volumes",
        "Shadow volumes",
        "Stencil shadow volumes: silhouettes from adjacency, z-pass and z-fail, caps, infinite far plane, many lights.",
        3,
        "V cycles the view: volumes, wireframe, the stencil count as a heatmap, silhouettes.\n"
        "Z: auto / z-pass / z-fail. Preset camera_in_volume: z-pass inverts the shadow, z-fail holds.\n"
        "S: silhouettes on the CPU or in a geometry shader. T: two-sided stencil or two passes.\n"
        "The header counts objects drawn z-pass and z-fail, open meshes, and the fill per light.\n"
        "Press M: against ground truth the only errors are on shadow boundaries.",
        true};
  }

  void declare(ParamRegistry& r) override {
    camera.target = {0, 0.8f, 0};
    r.addChoice("scene", &p_.scene, sceneNames(), "procedural scene (deterministic from its seed)");
    r.add("triangles", &p_.triangles, 10000, 1000000, "scene size: silhouette edges and volume fill grow with it");
    r.addChoice("view", &p_.view, {"lit", "volumes", "wireframe", "stencil", "silhouettes"}, "the inner buffers")
        .hotkey = "V";
    r.add("view_light", &p_.viewLight, 0, kLights - 1,
          "which light's volumes, stencil counts and silhouettes the views show");
    r.addChoice("method", &p_.method, {"auto", "z_pass", "z_fail"},
                "auto: z-fail only for casters whose volume can reach the near plane")
        .hotkey = "Z";
    r.addChoice("silhouettes", &p_.silhouettes, {"cpu", "gpu"},
                "CPU from the adjacency (cached), or a geometry shader with triangles_adjacency")
        .hotkey = "S";
    r.add("two_sided", &p_.twoSided, "glStencilOpSeparate: front and back faces in one pass (else two culled passes)")
        .hotkey = "T";
    r.addChoice("far", &p_.far, {"infinite", "depth_clamp"}, "infinite far plane, or a finite one with GL_DEPTH_CLAMP");
    r.addChoice("open_meshes", &p_.openMeshes, {"skip", "z_pass_only"},
                "open meshes cannot close a volume: cast nothing, or z-pass without caps");
    r.add("scissor", &p_.scissor, "limit each point/spot light's passes to the screen rectangle of its reach");
    r.add("fill_query", &p_.fillQuery, "an extra pass counting every volume fragment (samples passed), timed apart");
    r.addChoice("impl", &p_.impl, {"reference", "student"},
                "whose exercise code runs: silhouettes, projection, stencil ops, z-fail test");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia: the light shadows never take away");
    r.add("specular", &p_.specular, 0, 1, "ks");
    r.add("shininess", &p_.shininess, 1, 256, "the specular exponent");
    r.add("animate", &p_.animate, "orbit the point light: its volumes are rebuilt every frame").hotkey = "A";

    // The course's rig: a sun, a warm point light (both on), a spot and a green point light (off; see many_lights).
    const std::vector<Light> rig = lighting::courseLights();
    for (int i = 0; i < kLights; ++i) declareLight(r, i, p_.lights[i] = rig[std::size_t(i)]);
  }

  void init() override {
    for (gl::Program* p : {&ambient_, &lit_, &volume_, &volumeGs_, &heat_}) p->build();
    emptyVao_ = gl::makeVertexArray("fullscreen triangle");
    lineVao_ = gl::makeVertexArray("silhouette lines");
    lineBuffer_ = gl::makeBuffer(GL_ARRAY_BUFFER, "silhouette lines");
    for (int i = 0; i < kLights; ++i) fill_[i].query = gl::makeQuery("fill light " + std::to_string(i));
    loadScene();
  }

  MeasureSource measureSource() override {
    return {&scene_, std::uint64_t(revision_), {p_.lights, p_.lights + kLights}};
  }

  void update(const FrameInfo& f) override {
    if (p_.scene != builtScene_ || p_.triangles != builtTriangles_) loadScene();
    if (p_.animate) {
      const float a = float(f.time) * 0.6f;
      p_.lights[1].position = {4.0f * std::cos(a), p_.lights[1].position.y, 4.0f * std::sin(a)};
    }
  }

  void render(const FrameInfo& f) override {
    const bool student = p_.impl == Impl::Student;
    const float aspect = float(f.width) / float(f.height);
    // The projection with its far plane at infinity (or the finite one, with depth clamping).
    glm::mat4 proj = f.projection;
    if (p_.far == FarPlane::Infinite)
      proj = student && !f.godView
                 ? ex04::infinitePerspective(camera.fovY, aspect, camera.nearZ, volume::kInfiniteEpsilon)
                 : volume::makeFarInfinite(f.projection);
    const glm::mat4 viewProj = proj * f.view;
    // z-pass or z-fail is decided for the viewer's near plane, also when the god view draws.
    const volume::NearRect nearRect =
        volume::nearRect(camera.view(), camera.fovY, float(f.width) / float(f.height), camera.nearZ);

    // ==== 1. depth and ambient ======================================================================
    {
      auto t = scope("depth + ambient");
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);
      glEnable(GL_CULL_FACE);
      glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
      glClearStencil(0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
      ambient_.use();
      ambient_.set("uAmbient", glm::vec3(p_.ambient));
      drawScene(ambient_, viewProj, f.eye);
    }

    int zPass = 0, zFail = 0;
    for (int i = 0; i < kLights; ++i) {
      const Light& light = p_.lights[i];
      // A disabled light that is being measured still gets its count (its V), but adds no colour.
      if (!light.enabled && i != f.measureLight) continue;
      if (p_.view == View::Stencil && i != p_.viewLight) continue;
      const glm::vec4 L = volume::homogeneousLight(light);
      VolumeCache& cache = caches_[i];
      if (p_.silhouettes == Silhouettes::Cpu || p_.view == View::Silhouettes || i == p_.viewLight)
        buildVolumes(cache, L);
      // Which casters need z-fail: their volume can reach the viewer's near plane.
      std::vector<int> zFailObjects(scene_.objects.size(), 0);
      for (std::size_t o = 0; o < scene_.objects.size(); ++o) {
        if (!casts(o)) continue;
        const bool open = !adjacency_[scene_.objects[o].mesh].closed();
        const bool reach = open      ? false
                           : student ? ex04::volumeMayReachNearPlane(scene_.objectBounds(o), nearRect, L)
                                     : volume::volumeMayReachNearPlane(scene_.objectBounds(o), nearRect, L);
        zFailObjects[o] = p_.method == Method::ZFail ? !open : p_.method == Method::ZPass ? 0 : reach;
        (zFailObjects[o] ? zFail : zPass) += 1;
      }
      // The measured light is never scissored: outside its reach V would stay 0 and read as shadow.
      const bool scissored = p_.scissor && light.kind != LightKind::Directional && i != f.measureLight;
      if (scissored) {
        const auto s = volume::scissorForSphere(light.position, volume::lightReach(light), viewProj, f.width, f.height);
        if (s.width <= 0 || s.height <= 0) continue;  // wholly off screen: nothing to light
        glEnable(GL_SCISSOR_TEST);
        glScissor(s.x, s.y, s.width, s.height);
      }

      // ==== 2. stencil counting ====================================================================
      {
        auto t = scope("stencil light" + std::to_string(i));
        glClear(GL_STENCIL_BUFFER_BIT);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        if (p_.far == FarPlane::DepthClamp) glEnable(GL_DEPTH_CLAMP);
        for (bool fail : {false, true}) {
          const volume::StencilOps ops = student ? ex04::stencilOps(fail) : volume::stencilOps(fail);
          auto set = [](GLenum face, const volume::FaceStencilOps& o) {
            glStencilOpSeparate(face, toGl(o.stencilFail), toGl(o.depthFail), toGl(o.depthPass));
          };
          if (p_.twoSided) {  // both faces in one pass: no culling, an op per face orientation
            glDisable(GL_CULL_FACE);
            set(GL_FRONT, ops.front);
            set(GL_BACK, ops.back);
            drawVolumes(cache, L, zFailObjects, fail, viewProj);
          } else {  // two passes: front faces with the front ops, then back faces with the back ops
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            set(GL_FRONT_AND_BACK, ops.front);
            drawVolumes(cache, L, zFailObjects, fail, viewProj);
            glCullFace(GL_FRONT);
            set(GL_FRONT_AND_BACK, ops.back);
            drawVolumes(cache, L, zFailObjects, fail, viewProj);
            glCullFace(GL_BACK);
          }
        }
        glDisable(GL_DEPTH_CLAMP);
        glEnable(GL_CULL_FACE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      }
      if (p_.fillQuery && !f.godView) {
        auto t = scope("fill query");
        measureFill(i, cache, L, zFailObjects, viewProj);
      }

      // ==== 3. lit pass: add the light where the count is 0 ========================================
      {
        auto t = scope("lit light" + std::to_string(i));
        glStencilFunc(GL_EQUAL, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glDepthFunc(GL_EQUAL);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        // The measurement attachments (1-3) are overwritten, not summed; only the measured light
        // writes them at all (V = 1 where lit; the ambient pass left 0 everywhere else).
        for (GLuint a = 1; a <= 3; ++a) {
          glDisablei(GL_BLEND, a);
          const GLboolean on = i == f.measureLight ? GL_TRUE : GL_FALSE;
          glColorMaski(a, on, on, on, on);
        }
        if (!light.enabled) glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        lit_.use();
        setLight(light);
        drawScene(lit_, viewProj, f.eye);
        for (GLuint a = 0; a <= 3; ++a) glColorMaski(a, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_BLEND);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
      }
      if (p_.view == View::Stencil) drawStencilHeatmap();
      glDisable(GL_STENCIL_TEST);
      glDisable(GL_SCISSOR_TEST);
    }

    // ==== 4. views: the volumes, their wireframe, the silhouettes (and the god view's lines) =======
    VolumeCache& shown = caches_[std::size_t(p_.viewLight)];
    if (p_.view == View::Volumes || p_.view == View::Wireframe) {
      auto t = scope("volumes view");
      drawVolumesView(shown, viewProj);
    }
    if (p_.view == View::Silhouettes || f.godView) {
      auto t = scope("silhouettes view");
      drawSilhouettes(shown, viewProj);
    }
    pushGodViewShapes(shown);

    std::size_t open = 0;
    for (std::size_t o = 0; o < scene_.objects.size(); ++o) open += !adjacency_[scene_.objects[o].mesh].closed();
    if (f.godView) return;
    counters = {{"z-pass objects", std::to_string(zPass)},
                {"z-fail objects", std::to_string(zFail)},
                {"open meshes",
                 std::to_string(open) + (p_.openMeshes == OpenMeshes::Skip ? " (cast nothing)" : " (z-pass only)")},
                {"silhouette edges", std::to_string(shown.silhouette.size() / 2)}};
    for (int i = 0; i < kLights; ++i)
      if (p_.lights[i].enabled && p_.fillQuery)
        counters.push_back({"fill light" + std::to_string(i), std::to_string(fill_[i].samples)});
  }

 private:
  bool casts(std::size_t o) const {
    const SceneObject& obj = scene_.objects[o];
    return obj.castsShadow && (adjacency_[obj.mesh].closed() || p_.openMeshes == OpenMeshes::ZPassOnly);
  }

  void loadScene() {
    scene_ = makeScene(sceneNames()[p_.scene], 1, std::size_t(p_.triangles));
    gpu_ = gl::uploadScene(scene_, "scene");
    // ==== 0. edge adjacency, once per mesh: silhouettes later, closedness now ====================
    adjacency_.clear();
    adjacencyGpu_.clear();
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
      adjacency_.push_back(volume::buildAdjacency(scene_.meshes[m]));
      const volume::EdgeAdjacency& a = adjacency_.back();
      AdjacencyMesh g{gl::makeVertexArray("adjacency " + std::to_string(m)),
                      gl::makeBuffer(GL_ARRAY_BUFFER, "adjacency vertices"),
                      gl::makeBuffer(GL_ELEMENT_ARRAY_BUFFER, "adjacency indices"), GLsizei(a.adjacencyIndices.size())};
      glBindVertexArray(g.vao.id());
      glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(a.positions.size() * sizeof(glm::vec3)), a.positions.data(),
                   GL_STATIC_DRAW);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(a.adjacencyIndices.size() * 4), a.adjacencyIndices.data(),
                   GL_STATIC_DRAW);
      glBindVertexArray(0);
      adjacencyGpu_.push_back(std::move(g));
    }
    builtScene_ = p_.scene;
    builtTriangles_ = p_.triangles;
    ++revision_;
  }

  // The CPU path: silhouettes and caps per caster in its own space (the light taken there), then
  // moved to world space, all casters of one light in one buffer.
  void buildVolumes(VolumeCache& c, const glm::vec4& L) {
    const int key = revision_ * 4 + int(p_.impl) * 2 + int(p_.openMeshes);
    if (c.built == key && c.light == L) return;
    auto t = scope("cpu volumes");
    // impl=student: the student's silhouette test decides the sides.
    volume::buildSceneVolumes(
        scene_, adjacency_, L, [this](std::size_t o) { return casts(o); },
        p_.impl == Impl::Student ? &ex04::isSilhouette : nullptr, c);
    if (!c.vao) {
      c.vao = gl::makeVertexArray("volumes");
      c.buffer = gl::makeBuffer(GL_ARRAY_BUFFER, "volumes");
    }
    glBindVertexArray(c.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, c.buffer.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(c.triangles.size() * sizeof(glm::vec4)), c.triangles.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    c.light = L;
    c.built = key;
  }

  // The volumes of every caster whose method is `zFail` (z-fail ones with their caps).
  void drawVolumes(const VolumeCache& c, const glm::vec4& L, const std::vector<int>& zFailObjects, bool zFail,
                   const glm::mat4& viewProj) {
    if (p_.silhouettes == Silhouettes::Gpu) {
      volumeGs_.use();
      volumeGs_.set("uViewProj", viewProj);
      volumeGs_.set("uLight", L);
      volumeGs_.set("uCaps", zFail);
      for (std::size_t o = 0; o < scene_.objects.size(); ++o) {
        if (!casts(o) || bool(zFailObjects[o]) != zFail) continue;
        const AdjacencyMesh& g = adjacencyGpu_[scene_.objects[o].mesh];
        volumeGs_.set("uModel", scene_.objects[o].model);
        glBindVertexArray(g.vao.id());
        glDrawElements(GL_TRIANGLES_ADJACENCY, g.count, GL_UNSIGNED_INT, nullptr);
      }
      return;
    }
    std::vector<GLint> first;
    std::vector<GLsizei> count;
    for (std::size_t o = 0; o < c.first.size(); ++o)
      if (casts(o) && bool(zFailObjects[o]) == zFail && c.sides[o] + c.caps[o] > 0) {
        first.push_back(c.first[o]);
        count.push_back(c.sides[o] + (zFail ? c.caps[o] : 0));  // z-pass needs no caps
      }
    if (first.empty()) return;
    volume_.use();
    volume_.set("uViewProj", viewProj);
    volume_.set("uLight", L);
    volume_.set("uColor", glm::vec4(1));
    glBindVertexArray(c.vao.id());
    glMultiDrawArrays(GL_TRIANGLES, first.data(), count.data(), GLsizei(first.size()));
  }

  // Fill cost: every fragment the volumes rasterise (depth test off, nothing written), counted by
  // an occlusion query. Read a frame later, when it is ready, so the CPU never waits.
  void measureFill(int i, const VolumeCache& c, const glm::vec4& L, const std::vector<int>& zFailObjects,
                   const glm::mat4& viewProj) {
    Fill& fl = fill_[i];
    GLuint ready = 0;
    if (fl.issued) glGetQueryObjectuiv(fl.query.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready) glGetQueryObjectuiv(fl.query.id(), GL_QUERY_RESULT, &fl.samples);
    if (fl.issued && !ready) return;
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthFunc(GL_ALWAYS);
    glDisable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBeginQuery(GL_SAMPLES_PASSED, fl.query.id());
    for (bool fail : {false, true}) drawVolumes(c, L, zFailObjects, fail, viewProj);
    glEndQuery(GL_SAMPLES_PASSED);
    fl.issued = true;
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }

  // The stencil count as colours: one full-screen triangle per count, where the stencil equals it.
  void drawStencilHeatmap() {
    static const glm::vec3 ramp[] = {
        {0.1f, 0.1f, 0.6f}, {0.1f, 0.6f, 0.9f}, {0.2f, 0.8f, 0.3f}, {0.9f, 0.9f, 0.2f}, {1.0f, 0.5f, 0.1f}};
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    heat_.use();
    glBindVertexArray(emptyVao_.id());
    withoutMeasurement([&] {
      for (int k = 0; k <= 5; ++k) {  // k = 0: every count not listed (6+, and wrapped negatives) in red
        glStencilFunc(k == 0 ? GL_NOTEQUAL : GL_EQUAL, k, 0xff);
        heat_.set("uColor", glm::vec4(k == 0 ? glm::vec3(0.9f, 0.1f, 0.1f) : ramp[k - 1], 0.7f));
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
    });
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
  }

  void drawVolumesView(const VolumeCache& c, const glm::mat4& viewProj) {
    const bool wire = p_.view == View::Wireframe;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    if (wire) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    volume_.use();
    volume_.set("uViewProj", viewProj);
    volume_.set("uLight", c.light);
    volume_.set("uColor", glm::vec4(1.0f, 0.85f, 0.2f, wire ? 0.9f : 0.18f));
    glBindVertexArray(c.vao.id());
    withoutMeasurement([&] { glDrawArrays(GL_TRIANGLES, 0, GLsizei(c.triangles.size())); });
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }

  // The silhouette edges as lines (the volume shader draws w = 1 points where they are).
  void drawSilhouettes(const VolumeCache& c, const glm::mat4& viewProj) {
    std::vector<glm::vec4> v;
    for (const glm::vec3& p : c.silhouette) v.push_back(glm::vec4(p, 1));
    glBindVertexArray(lineVao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(glm::vec4)), v.data(), GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    withoutMeasurement([&] {
      glDepthFunc(GL_LEQUAL);
      volume_.use();
      volume_.set("uViewProj", viewProj);
      volume_.set("uColor", glm::vec4(1.0f, 0.2f, 0.9f, 1.0f));
      glDrawArrays(GL_LINES, 0, GLsizei(v.size()));
      glDepthFunc(GL_LESS);
    });
  }

  // The god view: the shown light's silhouette and a stub of each side quad toward infinity.
  void pushGodViewShapes(const VolumeCache& c) {
    const std::size_t step = std::max<std::size_t>(1, c.silhouette.size() / 4000) * 2;
    for (std::size_t k = 0; k + 1 < c.silhouette.size(); k += step) {
      const glm::vec3 a = c.silhouette[k], b = c.silhouette[k + 1];
      debug.line(a, b, {1.0f, 0.2f, 0.9f, 1.0f});
      const glm::vec3 dir =
          c.light.w != 0.0f ? glm::normalize(a - glm::vec3(c.light) / c.light.w) : -glm::normalize(glm::vec3(c.light));
      debug.line(a, a + 6.0f * dir, {1.0f, 0.85f, 0.2f, 0.5f});
    }
  }

  void drawScene(const gl::Program& prog, const glm::mat4& viewProj, const glm::vec3& eye) {
    prog.set("uViewProj", viewProj);
    prog.set("uEye", eye);
    prog.set("uTexture", 0);
    gl::SceneDrawOptions draw;
    draw.specular = p_.specular;
    draw.shininess = p_.shininess;
    gl::drawScene(prog, scene_, gpu_, draw);
  }

  void setLight(const Light& l) { gl::setLight(lit_, "uLight", l); }

  struct AdjacencyMesh {
    gl::VertexArray vao;
    gl::Buffer vertices, indices;
    GLsizei count = 0;
  };
  struct Fill {
    gl::Query query;
    bool issued = false;
    GLuint samples = 0;
  };

  Params p_;
  Scene scene_;
  gl::GpuScene gpu_;
  std::vector<volume::EdgeAdjacency> adjacency_;
  std::vector<AdjacencyMesh> adjacencyGpu_;
  VolumeCache caches_[kLights];
  Fill fill_[kLights];
  gl::Program ambient_{"04 depth + ambient", {"04_shadow_volumes/scene.vert", "04_shadow_volumes/ambient.frag"}};
  gl::Program lit_{"04 lit", {"04_shadow_volumes/scene.vert", "04_shadow_volumes/lit.frag"}};
  gl::Program volume_{"04 volume", {"04_shadow_volumes/volume.vert", "04_shadow_volumes/volume.frag"}};
  gl::Program volumeGs_{
      "04 volume gs",
      {"04_shadow_volumes/volume_gs.vert", "04_shadow_volumes/volume.geom", "04_shadow_volumes/volume.frag"}};
  gl::Program heat_{"04 stencil heatmap", {"common/fullscreen.vert", "04_shadow_volumes/heat.frag"}};
  gl::VertexArray emptyVao_, lineVao_;
  gl::Buffer lineBuffer_;
  int builtScene_ = -1, builtTriangles_ = -1, revision_ = 0;
};

int main(int argc, char** argv) { return runLesson<ShadowVolumeLesson>(argc, argv); }

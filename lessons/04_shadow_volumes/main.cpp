// Lesson 04: stencil shadow volumes, done right. The lecture's passes ([Tarantsev-L12], shadow
// volumes) made robust after Everitt and Kilgard, "Practical and Robust Stenciled Shadow Volumes"
// ([Everitt2002]), in the stencil-volume technique (lessons/04_shadow_volumes/stencil_volumes.cpp, whose
// numbered passes are this lesson's; shaders in shaders/04_shadow_volumes/):
//   0. edge adjacency           once per mesh: silhouettes later, open meshes found now
//   1. depth and ambient        the scene once: depth, ka Ia, and V = 0 for the measurement
//   per light (scissored to its reach):
//   2. stencil counting         the volumes: silhouette quads to infinity (w = 0), caps for z-fail;
//                               z-pass or z-fail per object (z-fail only if its volume can reach
//                               the near plane); two-sided stencil in one pass, or two passes
//   3. lit pass                 the scene again, adding the light where the count is 0
//   4. views                    volumes, wireframe, the stencil count as a heatmap, silhouettes
// Silhouettes come from an edge adjacency built once per mesh, on the CPU or in a geometry shader
// (triangles_adjacency). An infinite far plane (or GL_DEPTH_CLAMP) keeps the far caps unclipped.
// Open meshes are found when the adjacency is built and skipped or drawn z-pass only, on screen.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): silhouettes, the infinite projection, the stencil ops, the near-plane
// test; in GLSL (shaders/04_shadow_volumes/exercises.glsl) the extrusion to infinity.
// `--set impl=student` runs YOUR versions in the lesson.
#include <cmath>
#include <iostream>

#include "algorithms/lighting.hpp"
#include "app/lesson.hpp"
#include "core/light_rig.hpp"
#include "core/scene_gen.hpp"
#include "exercises.hpp"
#include "technique/scene_cache.hpp"
#include "stencil_volumes.hpp"

using namespace shadowlab;

namespace {

constexpr int kLights = 4;

struct Params {
  tech::SceneChoice scene{0, 40000};  // showcase: closed shapes on an open ground plane
  Impl impl = Impl::Reference;        // student: your exercises.cpp drives the lesson
  float ambient = 0.08f;
  float specular = 0.35f;
  float shininess = 48.0f;
  bool animate = false;  // orbit the point light: the volumes are rebuilt every frame
  // The course's rig: a sun and a warm point light on, a blue spot and a green point light off.
  std::array<Light, kLights> lights = courseRig();
};

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Stencil shadow volumes: silhouettes from adjacency, z-pass and z-fail, caps, infinite far plane, "
    "many lights.";
const char* const kHelp = R"(view (V) cycles: volumes, wireframe, the stencil count as a heatmap, silhouettes.
method (Z): auto, z-pass, z-fail. Preset camera_in_volume: z-pass inverts the shadow, z-fail holds.
silhouettes (K): on the CPU or in a geometry shader. two_sided (T): one stencil pass or two.
The header counts objects drawn z-pass and z-fail, open meshes, and the fill per light.
measure.overlay (M): against ground truth the only errors are on shadow boundaries.)";

}  // namespace

// The stencil-volume technique does the passes; the lesson picks the scene, the lights and the
// student's code, and shows the technique's own views.
class ShadowVolumeLesson : public Lesson {
 public:
  void declare(ParamRegistry& r) override {
    volumes_.declare(r, "");  // this lesson's subject, first: its parameters keep their bare names
    for (const auto& [name, key] : {std::pair{"view", "V"}, {"method", "Z"}, {"silhouettes", "K"}, {"two_sided", "T"}})
      r.setHotkey(name, key);
    tech::SceneCache::declare(r, &p_.scene, "procedural scene (deterministic from its seed)",
                              "scene size: silhouette edges and volume fill grow with it");
    camera.target = {0, 0.8f, 0};
    declareImpl(r, &p_.impl, "whose exercise code runs: silhouettes, projection, stencil ops, z-fail test");
    exercises.add("04.1", "isSilhouette", "no edge is a silhouette: no volume is drawn, nothing is shadowed");
    exercises.add("04.2", "infinitePerspective",
                  "the projection is the identity: the scene is out of view, the frame black");
    exercises.add("04.3", "stencilOps", "the stencil never counts: nothing is shadowed");
    exercises.add("04.4", "volumeMayReachNearPlane",
                  "method=auto never picks z-fail: wrong shadows with the camera in a volume");
    exercises.addGlsl("04.5", "extrudeToInfinity",
                      "silhouettes=gpu extrudes nothing: the volumes have no length, nothing is shadowed",
                      "silhouettes=gpu");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia: the light shadows never take away");
    r.add("specular", &p_.specular, 0, 1, "ks");
    r.add("shininess", &p_.shininess, 1, 256, "the specular exponent");
    r.add("animate", &p_.animate, "orbit the point light: its volumes are rebuilt every frame").hotkey = "L";

    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"04",
            "04_shadow_volumes",
            "Shadow volumes",
            kSummary,
            3,
            kHelp,
            true,
            90,
            {"02"},
            // the last four only where the browser draws otherwise than asked (stencil_volumes.cpp)
            {"z-pass objects", "z-fail objects", "silhouette edges", "silhouettes", "far", "wireframe", "fill query"}};
  }

  void init() override {
    applyImpl();  // a broken exercises.glsl stops a headless run at once
    volumes_.init();
  }

  MeasureSource measureSource() override {
    return {&scene_.scene(), scene_.revision(), {p_.lights.begin(), p_.lights.end()}};
  }

  void update(const FrameInfo& f) override {
    if (scene_.update(p_.scene) && tech::SceneCache::isModel(p_.scene)) useOpenMeshPath();
    if (p_.animate) {
      const float a = float(f.time) * 0.6f;
      p_.lights[1].position = {4.0f * std::cos(a), p_.lights[1].position.y, 4.0f * std::sin(a)};
    }
    applyImpl();
  }

  // impl=student: your silhouette test, projection, stencil ops, near-plane test and extrusion.
  void applyImpl() {
    volumes_.student = p_.impl == Impl::Student ? tech::StencilVolumes::Student{ex04::stencilOps, &ex04::isSilhouette,
                                                                                ex04::infinitePerspective,
                                                                                ex04::volumeMayReachNearPlane, true}
                                                : tech::StencilVolumes::Student{};
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c{f, camera, scene_, {p_.lights.begin(), p_.lights.end()}, timers, debug};
    // ==== 0. edge adjacency once per mesh, and which objects can cast a closed volume ===========
    volumes_.renderShadows(c);
    drawFrame(c);
    if (!f.godView) counters = volumes_.stats().counters();
    if (const auto key = volumes_.legend(); key && !f.godView) legends.push_back(*key);
  }

  // The shimmer figures (Lesson::redrawLit): passes 1-4 once more from another camera (the volumes
  // are exact: nothing should flip), leaving the god view's shapes as the frame left them.
  bool redrawLit(const FrameInfo& f) override {
    const DebugDraw shapes = debug;
    drawFrame({f, camera, scene_, {p_.lights.begin(), p_.lights.end()}, timers, debug});
    debug = shapes;
    return true;
  }

 private:
  void drawFrame(const tech::ShadowContext& c) {
    // ==== 1. depth and ambient: the scene once, its depth for every light's count ===============
    const tech::LitSettings lit{glm::vec3(p_.ambient), 0, p_.specular, p_.shininess};
    const tech::StencilVolumes::Frame frame = volumes_.beginFrame(c);  // the far plane at infinity
    volumes_.depthAndAmbient(frame, lit);
    for (int i = 0; i < kLights; ++i) {
      // ==== 2. stencil counting: each caster's volume, z-pass or z-fail (glStencilOpSeparate) ==
      // ==== 3. lit pass: the light added where the count is 0 (glStencilFunc(GL_EQUAL, 0)) =====
      volumes_.renderLight(frame, i, lit);  // scissored to the light's reach
    }
    // ==== 4. views: volumes, wireframe, the stencil count as a heatmap, silhouettes ==============
    volumes_.finishFrame(frame);
  }

  // Real models are rarely closed: skipped, their open meshes would cast nothing. A loaded model
  // with open edges switches open_meshes to z_pass_only (the panel shows it) and says so.
  void useOpenMeshPath() {
    // Mesh 0 is the ground (core/model_file's placeOnGround): open too, but it casts nothing either way.
    const std::vector<Mesh>& meshes = scene_.scene().meshes;
    std::size_t openMeshes = 0, openEdges = 0;
    for (std::size_t i = 1; i < meshes.size(); ++i) {
      const Topology t = analyseTopology(meshes[i]);
      openMeshes += !t.closed();
      openEdges += t.boundaryEdges + t.nonManifoldEdges + t.inconsistentEdges;
    }
    std::cerr << "04_shadow_volumes: " << scene_.scene().name << ": " << openEdges << " open edges in " << openMeshes
              << " of " << meshes.size() - 1 << " meshes";
    auto& open = volumes_.params().openMeshes;
    if (openEdges > 0 && open == tech::StencilVolumeParams::OpenMeshes::Skip) {
      open = tech::StencilVolumeParams::OpenMeshes::ZPassOnly;
      std::cerr << ": open_meshes=z_pass_only (their volumes have holes; z-pass counts them without caps)";
    }
    std::cerr << '\n';
  }

  Params p_;
  tech::SceneCache scene_{"04 scene"};
  tech::StencilVolumes volumes_;
};

int main(int argc, char** argv) { return runLesson<ShadowVolumeLesson>(argc, argv); }

// Lesson 02: shadow maps ([Williams1978], as [Boreskov2005] builds them; [Tarantsev-L12]).
//
//   pass 1: render depth from the light into a depth texture (no colour, polygon offset on)
//   pass 2: render from the eye; T = translate(0.5) * scale(0.5) * P_light * V_light takes each
//           point into the map, and V = (depth - bias <= stored depth) ? 1 : 0
//
// A spot light (its cone fits the light's perspective frustum), a depth texture in 16, 24 or 32F
// bits, the hardware comparison (sampler2DShadow, ARB_shadow) or the same comparison written in
// the shader, glPolygonOffset(factor, units) as sliders, and alpha-tested casters (leaf cards, a
// fence) whose holes must be discarded in the depth pass too.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the texture matrix, the depth comparison, a CPU shadow-map lookup.
#include <glm/gtc/matrix_transform.hpp>

#include "app/exercise_program.hpp"
#include "app/lesson.hpp"
#include "core/light_rig.hpp"
#include "core/mesh_gen.hpp"
#include "core/scene_gen.hpp"
#include "algorithms/light_cameras.hpp"
#include "algorithms/shadow_math.hpp"
#include "exercises.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/scene_draw.hpp"
#include "gl/shadow_map.hpp"
#include "technique/casters.hpp"
#include "technique/depth_prepass.hpp"
#include "technique/map_settings.hpp"
#include "technique/map_view.hpp"
#include "technique/pass_key.hpp"
#include "technique/scene_cache.hpp"
#include "technique/technique.hpp"

using namespace shadowlab;

namespace {

enum class View { Lit, Visibility, LightDepth, ShadowMap };
enum class Compare { Hardware, Manual, CpuVertex, Off };

struct Params {
  tech::SceneChoice scene{2, 100000};  // forest: alpha-tested casters; the depth pass draws all of it again
  int mapSize = 2048;                  // texels per side (one of tech::kMapSizes)
  gl::DepthFormat format = gl::DepthFormat::Depth24;  // 16 bits shows banding and acne first
  Compare compare = Compare::Hardware;                // ARB_shadow in the sampler, or the same test by hand
  float offsetFactor = 4.0f;                          // glPolygonOffset factor: bias grows with the depth slope
  float offsetUnits = 4.0f;                           // glPolygonOffset units: constant, in depth-format steps
  float bias = 0.0f;                                  // in-shader constant bias (texture depth units)
  bool alphaTest = true;                              // discard the cards' holes in the depth pass too
  View view = View::Lit;
  bool inset = true;                         // the shadow map in a corner
  Impl impl = Impl::Reference;               // student: your texture matrix and (cpu_vertex) lookup
  float lightNear = 2.0f, lightFar = 80.0f;  // the light frustum's depth range: precision lives here
  float ambient = 0.12f;
  bool animate = false;                                 // swing the spot around the scene
  tech::PrepassMode prepass = tech::PrepassMode::Auto;  // off while the frame budget halves the size
  Light light = forestSpot();                           // light0: a spot high over the forest
};

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Depth from the light into a texture, then a depth comparison through the texture matrix: a spot "
    "light's hard shadows.";
const char* const kHelp = R"(Pass 1 renders depth from the spot light; pass 2 compares every pixel's light-space depth.
Try: polygon offset 0 0 (acne everywhere); format (F) 16 bits; compare (C) manual: the same image;
alpha_test (T) off: leaf cards cast solid shadows; map_size 256: blocky edges; view=shadow_map;
view.god (O): the god view with the light frustum; measure.overlay (M): error and aliasing heatmaps.)";

}  // namespace

// The first shadow map, drawn by hand: the lesson's two passes are its own (the technique layer
// gives it the scene, the depth pass's caster loop and the map view).
class ShadowMapLesson : public Lesson {
 public:
  void declare(ParamRegistry& r) override {
    camera.aim({0, 1.5f, 0}, 30.0f, 0.55f);  // the forest from above the fence
    tech::SceneCache::declare(r, &p_.scene, "procedural scene (forest: alpha-tested leaves and fence)",
                              "scene size: both passes draw every triangle");
    tech::declareMapSize(r, "map_size", &p_.mapSize, "shadow-map resolution: texels per side");
    r.addChoice("format", &p_.format, {"16", "24", "32f"}, "depth texture format (ARB_depth_texture: 16, 24, 32F bits)")
        .hotkey = "F";
    r.addChoice("compare", &p_.compare, {"hardware", "manual", "cpu_vertex", "off"},
                "sampler2DShadow (ARB_shadow), the comparison in the shader, your CPU lookup per vertex, or none")
        .hotkey = "C";
    r.add("offset.factor", &p_.offsetFactor, 0, 10,
          "glPolygonOffset factor: scales with the depth slope of each triangle");
    r.add("offset.units", &p_.offsetUnits, 0, 100,
          "glPolygonOffset units: the smallest depth step of the format, times this");
    r.add("bias", &p_.bias, 0, 0.05f, "constant bias subtracted in the shader before the comparison");
    r.add("alpha_test", &p_.alphaTest, "discard alpha-tested texels in the depth pass (holes cast holes)").hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "light_depth", "shadow_map"},
                "lit, V alone, the fragment's depth in the light, or the map (linearised)")
        .hotkey = "V";
    r.add("inset", &p_.inset, "show the shadow map in a corner").hotkey = "I";
    declareImpl(r, &p_.impl, "whose exercise code: your texture matrix and CPU lookup");
    exercises.add("02.1", "shadowTextureMatrix", "the texture matrix is the identity: the shadows are wrong or gone");
    exercises.add("02.2", "depthCompare", "compare=cpu_vertex lights every vertex: no shadows");
    exercises.add("02.3", "shadowLookup (CPU)", "compare=cpu_vertex lights every vertex: no shadows");
    exercises.addGlsl("02.4", "shadowCompare", "compare=manual lights every pixel: no shadows", "compare=manual");
    exercises.addGlsl("02.5", "shadowLookup", "compare=manual lights every pixel: no shadows", "compare=manual");
    r.add("shadow.near", &p_.lightNear, 0.05f, 50,
          "the light frustum's near plane: depth precision depends on far/near");
    r.add("shadow.far", &p_.lightFar, 1, 500, "the light frustum's far plane");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia: what remains in the shadow");
    r.add("animate", &p_.animate, "swing the spot light around the scene").hotkey = "L";
    r.addChoice("depth_prepass", &p_.prepass, {"auto", "on", "off"},
                "depth first, then the lit shader once per pixel; auto: off at render scale 0.5 or less");
    declareLight(r, 0, p_.light);  // light0.*: position, direction, spot_outer (the frustum's fov is twice it)
  }

  LessonInfo info() const override {
    return {"02",
            "02_shadow_maps",
            "Shadow maps",
            kSummary,
            2,
            kHelp,
            true,
            90,
            {"01"},
            {"shadow map", "shadow triangles"}};
  }

  void init() override {
    casters_.build();
    prepass_.build();
    mapView_.build();
    unlit_.build();
    compareNearest_ = gl::makeCompareSampler(false, "02 compare sampler");
    rawDepth_ = gl::makeRawDepthSampler("02 raw depth sampler");
    gizmo_ = gl::uploadMesh(makeSphere(0.25f, 16, 8), "02 light gizmo");
  }

  MeasureSource measureSource() override { return {&scene_.scene(), scene_.revision(), {p_.light}}; }

  void update(const FrameInfo& f) override {
    if (scene_.update(p_.scene)) cpuVisibility_.clear();
    const int size = p_.mapSize;
    if (map_.size != size || map_.format != p_.format) map_ = gl::makeShadowMap(size, p_.format, "02 shadow map");
    if (p_.animate) {
      const float a = float(f.time) * 0.4f;
      p_.light.position = {18.0f * std::cos(a), p_.light.position.y, 18.0f * std::sin(a)};
      p_.light.direction = glm::normalize(glm::vec3(0, 1.5f, 0) - p_.light.position);
    }
  }

  void render(const FrameInfo& f) override {
    // The light camera: a perspective frustum around the spot's cone ([Boreskov2005]: good for spots).
    const shadow::LightCamera light =
        shadow::spotCamera(p_.light, p_.lightNear, p_.lightFar, scene_.casterBoxes(), false);
    const bool student = p_.impl == Impl::Student;
    const glm::mat4 textureMatrix = student ? ex02::shadowTextureMatrix(light.projection, light.view)
                                            : shadow::textureMatrix(light.projection, light.view);
    if (!f.godView) textureMatrix_ = textureMatrix;
    debug.frustum(light.viewProj(), {1.0f, 0.9f, 0.3f, 1.0f});
    debug.name({1.0f, 0.9f, 0.3f, 1.0f}, "the light's frustum: what its map covers");
    debug.cone(p_.light.position, glm::normalize(p_.light.direction), p_.light.spotOuter, 12.0f,
               {1.0f, 0.7f, 0.2f, 1.0f});
    debug.name({1.0f, 0.7f, 0.2f, 1.0f}, "the spot's cone");

    // ==== 1. shadow map: depth from the light ======================================================
    // The god view re-renders the frame from outside: the map the viewer's frame made is reused;
    // so is a map nothing invalidated (the light, the casters and the depth pass unchanged).
    tech::PassKey key;
    key << scene_.revision() << light.viewProj() << map_.size << map_.format << p_.offsetFactor << p_.offsetUnits
        << p_.alphaTest;
    mapReused_ = key == rendered_;
    if (!f.godView && !mapReused_) {
      rendered_ = std::move(key);
      auto t = scope("shadow map");
      gl::beginShadowPass(map_);
      glEnable(GL_POLYGON_OFFSET_FILL);  // [Boreskov2005]: glPolygonOffset(4, 4) against self-shadowing
      glPolygonOffset(p_.offsetFactor, p_.offsetUnits);
      shadowTriangles_ = casters_.draw(scene_, light.viewProj(), {}, {p_.alphaTest, false});
      glDisable(GL_POLYGON_OFFSET_FILL);
      glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer);
      glViewport(0, 0, f.width, f.height);
    }
    counters = mapCounters(student);

    // ==== 1b. CPU lookup per vertex (compare=cpu_vertex: the exercises' lookup on a read-back) =====
    if (p_.compare == Compare::CpuVertex && !f.godView) {
      auto t = scope("cpu lookup");
      lookUpVerticesOnCpu(textureMatrix, student);
    }

    // ==== 2. the scene from the eye, V from the map ================================================
    // Depth first, with the scene's own vertex shader (the forest's cards overlap many times over:
    // the lit shader then runs once per pixel, where the depth test passes EQUAL). Not while the
    // frame budget draws at half size or less: the forest's triangles then cost more than its overdraw.
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (p_.view != View::ShadowMap) {
      const bool prepass = tech::prepassOn(p_.prepass, f.renderScale);
      {
        auto t = scope(prepass ? "depth pre-pass" : "view culling");
        prepass_.begin(scene_, f.projection * f.view, prepass);
      }
      auto t = scope("scene");
      drawScene(f, textureMatrix, prepass);
      prepass_.end();
      counters.push_back({"objects out of view", std::to_string(prepass_.culled())});
      counters.push_back({"drawn nearest card first", std::to_string(prepass_.sorted()) + " crowns"});
      counters.push_back({"depth pre-pass", prepass ? "on" : "off"});
    }

    // ==== 3. views: the shadow map (full screen or inset), the light ==============================
    if (p_.view == View::ShadowMap || (p_.inset && !f.godView)) {
      auto t = scope("map view");
      const bool full = p_.view == View::ShadowMap;
      const int side = full ? std::min(f.width, f.height) : std::min(f.width, f.height) / 3;
      mapView_.draw(map_, full ? (f.width - side) / 2 : f.width - side - 8, full ? 0 : 8, side, side,
                    glm::vec2(p_.lightNear, p_.lightFar));
      if (!full) insets.push_back({"shadow-map inset", f.width - side - 8, 8, side, side});
    }
    if (p_.view != View::ShadowMap) {
      auto t = scope("gizmo");
      unlit_.use();
      unlit_.set("uMvp", f.projection * f.view * glm::translate(glm::mat4(1), p_.light.position));
      unlit_.set("uColor", glm::vec4(1.0f, 0.9f, 0.4f, 1.0f));
      gizmo_.draw();
    }
  }

 private:
  // The header's figures of the shadow pass: what it drew (a kept map: what it cost when drawn,
  // marked kept), the map, and where the comparison runs.
  std::vector<Counter> mapCounters(bool student) const {
    const std::uint64_t texels = std::uint64_t(map_.size) * std::uint64_t(map_.size);
    return {
        {"shadow triangles", mapReused_ ? tech::drawnFigure(0, shadowTriangles_) : std::to_string(shadowTriangles_)},
        {"shadow texels", mapReused_ ? tech::drawnFigure(0, texels) : std::to_string(texels)},
        {"culled casters", "0"},
        {"maps reused", mapReused_ ? "1" : "0"},
        {"shadow map", std::to_string(map_.size) + "^2 " + gl::depthFormatName(map_.format)},
        {"comparison", p_.compare == Compare::Hardware ? "sampler2DShadow"
                       : p_.compare == Compare::Manual ? "in the shader"
                       : p_.compare == Compare::CpuVertex
                           ? (student ? "CPU per vertex, student code" : "CPU per vertex")
                           : "off"}};
  }

  // The shimmer figures (Lesson::redrawLit): pass 2 once more from another camera, with this frame's map.
  bool redrawLit(const FrameInfo& f) override {
    if (p_.view == View::ShadowMap) return false;
    glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer);
    glViewport(0, 0, f.width, f.height);
    glEnable(GL_DEPTH_TEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    prepass_.begin(scene_, f.projection * f.view, false);
    drawScene(f, textureMatrix_, false);
    prepass_.end();
    return true;
  }

  void drawScene(const FrameInfo& f, const glm::mat4& textureMatrix, bool afterPrepass) {
    // Compiled for the comparison, the view and the pre-pass in use (constants in that variant).
    std::vector<std::string> defines = {"COMPARE " + std::to_string(int(p_.compare)),
                                        "VIEW " + std::to_string(int(p_.view))};
    if (afterPrepass) defines.push_back("DEPTH_PREPASS 1");
    const gl::Program& program = sceneVariants_.get(defines);
    program.use();
    program.set("uViewProj", f.projection * f.view);
    program.set("uEye", f.eye);
    program.set("uTextureMatrix", textureMatrix);
    program.set("uAmbient", glm::vec3(p_.ambient));
    program.set("uCompare", int(p_.compare));
    program.set("uBias", p_.bias);
    program.set("uMapSize", float(map_.size));
    program.set("uView", int(p_.view));
    program.set("uMeasureLight", f.measureLight);
    program.set("uTexture", 0);
    program.set("uShadowMap", 1);  // one texture on two units: one sampler type each
    program.set("uShadowDepth", 2);
    gl::setLight(program, "uLight", p_.light);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, map_.texture.id());
    glBindSampler(1, compareNearest_.id());
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, map_.texture.id());
    glBindSampler(2, rawDepth_.id());
    gl::SceneDrawOptions draw;
    draw.filter = [this](std::size_t i) { return prepass_.inView(i); };  // the pre-pass's view culling
    draw.viewer = glm::vec4(f.eye, 1.0f);      // each crown's nearest cards first: fewer fragments shaded
    draw.beforeDraw = [this](std::size_t i) {  // compare=cpu_vertex: V per vertex at attribute 3
      if (p_.compare == Compare::CpuVertex && i < cpuVisibility_.size()) {
        glBindBuffer(GL_ARRAY_BUFFER, cpuVisibility_[i].id());
        glEnableVertexAttribArray(3);
        glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
      } else {
        glDisableVertexAttribArray(3);
        glVertexAttrib1f(3, 1.0f);
      }
    };
    gl::drawScene(program, scene_.scene(), scene_.gpu(), draw);
    glBindSampler(1, 0);
    glBindSampler(2, 0);
    glActiveTexture(GL_TEXTURE0);
  }

  // The map read back (row 0 is v = 0, as shadow::DepthMap wants), and V per vertex with the
  // chosen implementation of the lookup: what the GPU does per pixel, done by hand.
  void lookUpVerticesOnCpu(const glm::mat4& textureMatrix, bool student) {
    std::vector<float> texels(std::size_t(map_.size) * std::size_t(map_.size));
    glBindTexture(GL_TEXTURE_2D, map_.texture.id());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
    const shadow::DepthMap map(map_.size, map_.size, std::move(texels));
    const Scene& scene = scene_.scene();
    while (cpuVisibility_.size() < scene.objects.size())
      cpuVisibility_.push_back(gl::makeBuffer(GL_ARRAY_BUFFER, "02 cpu visibility"));
    std::vector<float> v;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const SceneObject& o = scene.objects[i];
      const Mesh& mesh = scene.meshes[o.mesh];
      v.resize(mesh.positions.size());
      for (std::size_t k = 0; k < v.size(); ++k) {
        const glm::vec3 uvz = shadow::shadowCoord(textureMatrix, glm::vec3(o.model * glm::vec4(mesh.positions[k], 1)));
        v[k] = student ? ex02::shadowLookup(map, uvz, p_.bias) : shadow::shadowLookup(map, uvz, p_.bias);
      }
      glBindBuffer(GL_ARRAY_BUFFER, cpuVisibility_[i].id());
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STREAM_DRAW);
    }
  }

  Params p_;
  tech::SceneCache scene_{"02 scene"};
  gl::ShadowMap map_;
  gl::Sampler compareNearest_, rawDepth_;
  tech::CasterPass casters_{"02 depth"};
  tech::DepthPrepass prepass_{"02 depth pre-pass", "02_shadow_maps/scene.vert"};
  // GLSL exercises 02.4, 02.5: the student's build of the scene shader with impl=student.
  ExerciseProgram sceneVariants_{"02 scene", {"02_shadow_maps/scene.vert", "02_shadow_maps/scene.frag"}, [this] {
                                   return p_.impl == Impl::Student;
                                 }};
  tech::DepthMapView mapView_;
  gl::Program unlit_{"unlit", {"common/unlit.vert", "common/unlit.frag"}};
  gl::GpuMesh gizmo_;
  std::vector<gl::Buffer> cpuVisibility_;  // per object, V per vertex (compare=cpu_vertex)
  std::size_t shadowTriangles_ = 0;
  tech::PassKey rendered_;  // what the map holds
  bool mapReused_ = false;
  glm::mat4 textureMatrix_{1.0f};  // the viewer's frame's (redrawLit)
};

int main(int argc, char** argv) { return runLesson<ShadowMapLesson>(argc, argv); }

// Lesson 01: lighting. The lecture's illumination model with the visibility term V_i ([Tarantsev-L12]):
//
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (R_i.V)^pow]
//
// Three lights of the three kinds (directional, point, spot), Phong or Blinn-Phong highlights,
// attenuation, texture modulate, light gizmos. V_i is fixed at 1 here: every pixel that faces a
// light is lit, which is exactly what the rest of the course sets out to correct.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the lighting term, the NDC-to-texture matrix, attenuation, the spot
// cone. `--set impl=student` shades every vertex on the CPU with your functions.
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/lesson.hpp"
#include "core/light_rig.hpp"
#include "algorithms/lighting.hpp"
#include "core/mesh_gen.hpp"
#include "core/scene_gen.hpp"
#include "exercises.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/scene_draw.hpp"
#include "technique/scene_cache.hpp"

using namespace shadowlab;

namespace {

enum class View { Lit, Normals, Albedo, NdcRemap };
enum class Shading { PerPixelGpu, PerVertexCpu };

struct Params {
  tech::SceneChoice scene{0, 100000};      // showcase: shapes on a plane; shading cost grows with size
  View view = View::Lit;                   // debug views: what the shader sees
  Impl impl = Impl::Reference;             // student: your exercises.cpp drives the shading
  Shading shading = Shading::PerPixelGpu;  // per-vertex CPU shading shows Gouraud's artefacts
  float ambient = 0.08f;                   // ka Ia: the light that reaches everywhere
  float specular = 0.35f;                  // ks: strength of the highlight
  float shininess = 48.0f;                 // pow: size of the highlight (larger is smaller)
  bool blinn = true;                       // (N.H)^pow instead of the lecture's (R.V)^pow
  bool textures = true;                    // modulate: texture colour times material colour
  bool gizmos = true;                      // draw where the lights are
  bool animate = false;                    // move the point light around the scene
  // The course's rig but its fourth: the sun and a warm point light on, a blue spot off.
  Light lights[3] = {courseRig()[0], courseRig()[1], courseRig()[2]};
};

constexpr int kLightCount = 3;

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "The illumination model with the visibility term V_i: ambient, diffuse, specular, attenuation, three "
    "kinds of light.";
const char* const kHelp = R"(Orbit around the scene and move the lights (F3: the parameter panel).
Try: turn the lights on one at a time (light0.enabled 1, light1.enabled 2, light2.enabled 3);
compare Phong and Blinn highlights (blinn, B); raise light1.attenuation's quadratic term;
set view=normals and view=ndc_remap. Nothing casts a shadow: V_i = 1 everywhere, what lessons 02+ fix.
measure.overlay (M): the ground truth (Embree rays) marks every pixel lit here but in shadow in red.)";

}  // namespace

// No shadows yet: the lesson draws the scene itself, lit by the lecture's model with V_i = 1.
class LightingLesson : public Lesson {
 public:
  void declare(ParamRegistry& r) override {
    camera.target = {0, 0.8f, 0};
    tech::SceneCache::declare(r, &p_.scene, "procedural scene (deterministic from its seed)",
                              "scene size in triangles: the cost of every pass");
    r.addChoice("view", &p_.view, {"lit", "normals", "albedo", "ndc_remap"}, "what the fragment shader outputs")
        .hotkey = "V";
    declareImpl(r, &p_.impl, "whose exercise code shades (student: CPU per vertex)");
    exercises.add("01.1", "lightContribution: the lighting term",
                  "impl=student shades with it: every surface is black but for the ambient light");
    exercises.add("01.2", "ndcToTexture: NDC to [0,1]^3", "view=ndc_remap shows raw NDC, half of it clamped black");
    exercises.add("01.3", "attenuation", "the point and spot lights do not fade with distance");
    exercises.add("01.4", "spotFactor: the spot cone", "a spot light has no cone: it lights every direction");
    r.addChoice("shading", &p_.shading, {"pixel_gpu", "vertex_cpu"},
                "per-pixel on the GPU, or per-vertex on the CPU (Gouraud)");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia: light that reaches everywhere, even where V_i = 0");
    r.add("specular", &p_.specular, 0, 1, "ks: how strong the highlight is");
    r.add("shininess", &p_.shininess, 1, 256, "the exponent pow: how tight the highlight is");
    r.add("blinn", &p_.blinn, "Blinn's (N.H)^pow instead of the lecture's (R.V)^pow").hotkey = "B";
    r.add("textures", &p_.textures, "modulate: texture colour times material colour").hotkey = "T";
    r.add("gizmos", &p_.gizmos, "draw the lights").hotkey = "G";
    r.add("animate", &p_.animate, "orbit the point light around the scene").hotkey = "L";

    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"01", "01_lighting", "Lighting", kSummary, 1, kHelp, true, 60, {}, {"shading"}};
  }

  void init() override {
    unlit_.build();
    gizmo_ = gl::uploadMesh(makeSphere(0.12f, 16, 8), "light gizmo");
  }

  // The ground truth traces the same scene toward the same lights: every pixel this lesson lights
  // although the reference says it is in shadow shows up as a light leak.
  MeasureSource measureSource() override {
    return {&scene_.scene(), scene_.revision(), {p_.lights, p_.lights + kLightCount}};
  }

  // A recorded path moves the sun (the light measured by default).
  void applyPathLight(const glm::vec3& position, const glm::vec3& direction) override {
    p_.lights[0].position = position;
    if (glm::length(direction) > 0) p_.lights[0].direction = glm::normalize(direction);
  }

  void update(const FrameInfo& f) override {
    if (scene_.update(p_.scene)) colors_.clear();
    if (p_.animate) {
      const float a = float(f.time) * 0.6f;
      p_.lights[1].position = {4.0f * std::cos(a), p_.lights[1].position.y, 4.0f * std::sin(a)};
    }
  }

  void render(const FrameInfo& f) override {
    const glm::mat4 viewProj = f.projection * f.view;
    const bool cpu = p_.impl == Impl::Student || p_.shading == Shading::PerVertexCpu;
    counters = {{"triangles", std::to_string(scene_.scene().triangleCount())},
                {"shading", cpu ? (p_.impl == Impl::Student ? "CPU per vertex, student code" : "CPU per vertex")
                                : "GPU per pixel"}};

    // ==== 1. CPU shading (only for vertex_cpu or impl=student) ====================================
    if (cpu) {
      auto t = scope("cpu shading");
      shadeVerticesOnCpu();
    }

    // ==== 2. the scene, lit by the illumination model =============================================
    {
      auto t = scope("scene");
      glEnable(GL_DEPTH_TEST);
      glEnable(GL_CULL_FACE);
      glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      const int view = cpu && p_.view == View::Lit ? 4 : int(p_.view);
      const gl::Program& program = sceneProgram(view);
      program.use();
      program.set("uViewProj", viewProj);
      program.set("uEye", f.eye);
      program.set("uAmbient", glm::vec3(p_.ambient));
      program.set("uBlinn", p_.blinn);
      program.set("uView", view);
      program.set("uNdcToTexture", p_.impl == Impl::Student ? ex01::ndcToTexture() : lighting::ndcToTexture());
      program.set("uTexture", 0);
      program.set("uMeasureLight", f.measureLight);
      setLightUniforms(program);
      gl::SceneDrawOptions draw;
      draw.textures = p_.textures;
      draw.specular = p_.specular;
      draw.shininess = p_.shininess;
      draw.beforeDraw = [this](std::size_t i) { bindVertexColors(i); };
      gl::drawScene(program, scene_.scene(), scene_.gpu(), draw);  // beforeDraw sets attribute 3 for every object
    }

    // ==== 3. light gizmos ===========================================================================
    if (p_.gizmos) {
      auto t = scope("gizmos");
      unlit_.use();
      for (const Light& l : p_.lights) {
        if (!l.enabled) continue;
        const glm::vec3 at = l.kind == LightKind::Directional ? camera.target - 6.0f * l.direction : l.position;
        if (l.kind == LightKind::Spot) {
          debug.cone(l.position, l.direction, l.spotOuter, 6.0f, glm::vec4(l.color, 1));
          debug.name(glm::vec4(l.color, 1), "a spot's cone");
        }
        unlit_.set("uMvp", viewProj * glm::translate(glm::mat4(1), at));
        unlit_.set("uColor", glm::vec4(glm::min(l.color * 1.5f, glm::vec3(1)), 1));
        gizmo_.draw();
      }
    }
  }

 private:
  // The scene program compiled for what is in use: the enabled lights and their kinds, the view,
  // Phong or Blinn (a software rasteriser pays for every branch a uniform would switch).
  const gl::Program& sceneProgram(int view) {
    std::string kinds;
    int n = 0;
    for (const Light& l : p_.lights)
      if (l.enabled) kinds += (n++ ? ", " : "") + std::to_string(int(l.kind));
    for (; n < 4; ++n) kinds += n ? ", 0" : "0";
    const int enabled =
        int(std::count_if(std::begin(p_.lights), std::end(p_.lights), [](const Light& l) { return l.enabled; }));
    return sceneVariants_.get({"LIGHT_COUNT " + std::to_string(enabled), "LIGHT_KINDS " + kinds,
                               "VIEW " + std::to_string(view), std::string("BLINN ") + (p_.blinn ? "1" : "0")});
  }

  // Only the enabled lights go to the shader: a software rasteriser runs every loop iteration for
  // every pixel, so a switched-off light must cost nothing.
  void setLightUniforms(const gl::Program& program) {
    int n = 0;
    for (const Light& l : p_.lights)
      if (l.enabled) gl::setLight(program, "uLights[" + std::to_string(n++) + "]", l);
    program.set("uLightCount", n);
  }

  // The CPU-shaded colours of object i at attribute 3 (vertex_cpu shading), or a constant.
  void bindVertexColors(std::size_t i) {
    if (i < colors_.size()) {
      glBindBuffer(GL_ARRAY_BUFFER, colors_[i].id());
      glEnableVertexAttribArray(3);
      glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    } else {
      glDisableVertexAttribArray(3);
      glVertexAttrib3f(3, 0, 0, 0);
    }
  }

  // The same model as the shader, evaluated per vertex with the chosen implementation: with
  // impl=student every term comes from the student's exercises.cpp.
  void shadeVerticesOnCpu() {
    const bool student = p_.impl == Impl::Student;
    const glm::vec3 eye = camera.position();
    const Scene& scene = scene_.scene();
    while (colors_.size() < scene.objects.size()) colors_.push_back(gl::makeBuffer(GL_ARRAY_BUFFER, "cpu colours"));
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const SceneObject& o = scene.objects[i];
      const Mesh& mesh = scene.meshes[o.mesh];
      const Material& m = scene.materials[o.material];
      const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(o.model));
      scratch_.resize(mesh.positions.size());
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = glm::vec3(o.model * glm::vec4(mesh.positions[v], 1));
        glm::vec3 N = glm::normalize(normalMatrix * mesh.normals[v]);
        const glm::vec3 V = glm::normalize(eye - p);
        if (m.twoSided && glm::dot(N, V) < 0) N = -N;
        glm::vec3 c = glm::vec3(p_.ambient) * m.albedo;
        for (const Light& l : p_.lights) {
          if (!l.enabled) continue;
          const glm::vec3 L = l.toLight(p);
          float fatt = 1.0f, cone = 1.0f;
          if (l.kind != LightKind::Directional) {
            const float d = l.distanceTo(p);
            fatt = student ? ex01::attenuation(l.attenuation, d) : lighting::attenuation(l.attenuation, d);
          }
          if (l.kind == LightKind::Spot) {
            const float cosAngle = glm::dot(glm::normalize(l.direction), -L);
            cone = student ? ex01::spotFactor(cosAngle, l.spotInner, l.spotOuter)
                           : lighting::spotFactor(cosAngle, l.spotInner, l.spotOuter);
          }
          const glm::vec3 I = l.color * l.intensity * cone;
          c += student ? ex01::lightContribution(N, L, V, I, fatt, 1.0f, m.albedo, p_.specular, p_.shininess)
                       : (p_.blinn ? lighting::lightContributionBlinn : lighting::lightContribution)(
                             N, L, V, I, fatt, 1.0f, m.albedo, p_.specular, p_.shininess);
        }
        scratch_[v] = c;  // the shader modulates it by the texture
      }
      glBindBuffer(GL_ARRAY_BUFFER, colors_[i].id());
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(scratch_.size() * sizeof(glm::vec3)), scratch_.data(), GL_STREAM_DRAW);
    }
  }

  Params p_;
  tech::SceneCache scene_{"01 scene"};
  gl::ProgramVariants sceneVariants_{"01 scene", {"01_lighting/scene.vert", "01_lighting/scene.frag"}};
  gl::Program unlit_{"unlit", {"common/unlit.vert", "common/unlit.frag"}};
  gl::GpuMesh gizmo_;
  std::vector<gl::Buffer> colors_;  // per object, CPU-shaded vertex colours
  std::vector<glm::vec3> scratch_;
};

int main(int argc, char** argv) { return runLesson<LightingLesson>(argc, argv); }

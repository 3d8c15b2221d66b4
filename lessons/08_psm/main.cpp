// Lesson 08: Perspective Shadow Maps, the original ([Stamminger2002], as [Kozlov2004] §2-3
// describes it). The depth map is
// rendered and applied AFTER the camera's projection, in its post-projective space, where the view
// frustum is the unit cube and near things are big: near shadows get more texels. The PSM
// technique (lessons/08_psm/psm.cpp, shaders/08_psm/shadow_psm.frag) with every fix off:
//   the light there    h = P V L: a finite point (a point light, or a directional one on the plane
//                      at infinity behind the far face), or a direction (parallel to the near plane)
//   behind the camera  the light's rays reach the scene through infinity; the original slides a
//                      virtual camera back until every potential caster is in front of it
//   the light camera   fitted to every object inside the (virtual) view frustum, one map however
//                      wide its cone; the constant depth bias
// The lesson is its picture: the post-projective view (P) draws the squashed scene, the unit cube,
// the light where it lands, its light camera and the virtual camera's slide. Against it, lesson
// 03's uniform map at the same texels (technique=uniform, A/B preset versus_uniform).
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the post-projective light, the virtual camera's slide; in GLSL
// (shaders/08_psm/exercises.glsl) the lookup in the map; `--set impl=student` runs yours.
#include <algorithm>

#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "core/light_rig.hpp"
#include "exercises.hpp"
#include "technique/post_projective_view.hpp"
#include "psm.hpp"
#include "03_shadow_quality/uniform_maps.hpp"

using namespace shadowlab;

namespace {

enum class Technique { Psm, Uniform };
enum class View { Lit, Visibility, Map };
constexpr int kLights = 2;

struct Params {
  tech::SceneChoice scene{1, 60000};     // the city: straight edges show where the texels went
  Technique technique = Technique::Psm;  // the original PSM, or lesson 03's uniform map
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your post-projective light and virtual slide
  bool equalTexels = true;      // the uniform map gets the PSM's texels (map_size)
  bool turn = false;            // the camera turns (a caster leaves the view)
  float turnSpeed = 0.35f;      // radians per second
  float ambient = 0.1f;
  // A sun ahead of the camera (in front: a finite point behind the far face); a point light (off).
  Light lights[kLights] = {courseSun({0.6f, -1.0f, 0.7f}), courseLamp({3.0f, 6.0f, -6.0f})};
};

const char* const kSummary =
    "The original perspective shadow map: the depth map in the camera's post-projective space, the light "
    "there, the virtual camera slid back for a light behind; the post-projective view.";
const char* const kHelp = R"(view.post (P): the post-projective view (inset, full): the unit cube, the squashed scene,
the light where it lands (red: behind the camera), the light camera and the slide.
Presets: overhead (the best case), side, behind (the slide), facing (dueling frusta).
technique (T): the uniform map at equal texels. turn (Y) turns the camera: watch the slide jump.
measure.overlay (M): ground truth (leaks red, false shadows blue; aliasing m). view.god (O).)";

// The lesson's exercises as the technique's replaceable steps (impl=student).
psm::PostProjectiveLight studentLight(const glm::dmat4& viewProj, const glm::dvec4& light) {
  const glm::dvec4 r = ex08::postProjectiveLight(viewProj, light);
  psm::PostProjectiveLight out;
  // The student's answer as a homogeneous point, h / |h.w|: the same point, on the same side.
  out.homogeneous = r.w == 0.0 ? glm::dvec4(glm::dvec3(r), 0.0) : glm::dvec4(glm::dvec3(r) * r.w, r.w);
  const glm::dvec3 p(r);
  const double len = glm::length(p);
  if (r.w == 0.0 || !(len > 0.0) || !std::isfinite(len)) {  // a direction (or nonsense: one, finite)
    out.kind = psm::PostLightKind::Direction;
    out.direction = len > 0.0 && std::isfinite(len) ? p / len : glm::dvec3(0, 0, 1);
    return out;
  }
  out.kind = r.w > 0.0 ? psm::PostLightKind::InFront : psm::PostLightKind::Behind;
  out.position = p;
  out.direction = p / len;
  return out;
}

double studentShift(const psm::CameraFrustum& camera, std::span<const Aabb> casters) {
  std::vector<glm::dvec3> corners;
  for (const Aabb& b : casters)
    for (int i = 0; i < 8; ++i)
      corners.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
  return ex08::virtualCameraShift(camera.view, camera.zNear, corners);
}

}  // namespace

class OriginalPsmLesson : public tech::ShadowLesson {
 public:
  OriginalPsmLesson() : ShadowLesson("08", /*pathMovesLight=*/true) {}

  void declare(ParamRegistry& r) override {
    camera.aim({0, 2, 0}, 45.0f, 0.45f);  // a city block from above: shadows near and far
    camera.nearZ = 1.0f;                  // Zf/Zn = 200: the post-projective cube is not all far face
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what the shadow passes draw");
    r.addChoice("technique", &p_.technique, {"psm", "uniform"},
                "the original perspective shadow map (this lesson), or lesson 03's uniform map at equal texels")
        .hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "map"}, "lit, V of the measured light, or light 0's map")
        .hotkey = "V";
    declareImpl(r, &p_.impl, "whose post-projective light and virtual camera slide the PSM runs");
    exercises.add("08.1", "postProjectiveLight", "the PSM's light is a direction along +z: its shadows are wrong");
    exercises.add("08.2", "virtualCameraShift: the slide", "no slide: casters behind the camera cast no shadow");
    exercises.addGlsl("08.3", "psmMapCoords", "every point is outside the maps: no shadows");
    r.add("equal_texels", &p_.equalTexels, "the uniform map gets the PSM's map_size (the same texels)");
    r.add("turn", &p_.turn, "turn the camera (turn.speed): a caster leaves the view").hotkey = "Y";
    r.add("turn.speed", &p_.turnSpeed, -1, 1, "how fast the camera turns, radians per second");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    psm_.declare(r, "");  // the subject: bare names (the fixes are lesson 09's, all off here)
    uniform_.declare(r, "uniform.");
    postView_.declare(r);
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"08",
            "08_psm",
            "Perspective shadow maps",
            kSummary,
            4,
            kHelp,
            true,
            120,
            {"03"},
            {"light0 light", "light0 warp's predicted m", "light0 cone", "light0 post-projective depth"}};
  }

  void init() override {
    psm_.init();
    uniform_.init();
    postView_.init();
  }

  void update(const FrameInfo& f) override {
    scene_.update(p_.scene);
    if (p_.turn) camera.yaw += float(f.dt) * p_.turnSpeed;
    if (p_.equalTexels) uniform_.params().mapSize = psm_.maps().params().mapSize;
    // impl=student: your post-projective light (08.1), slide (08.2) and lookup in the map (08.3).
    tech::PerspectiveShadowMaps::Student student;
    if (p_.impl == Impl::Student) {
      student.toPostProjective = studentLight;
      student.virtualShift = studentShift;
      student.glslLookup = true;
    }
    psm_.student = student;
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c = context(f);
    tech::ShadowTechnique& technique = p_.technique == Technique::Psm ? static_cast<tech::ShadowTechnique&>(psm_)
                                                                      : static_cast<tech::ShadowTechnique&>(uniform_);

    shadowPasses(c, technique, p_.technique == Technique::Psm, [&] {  // (else lesson 03's uniform map)
      // ==== 1. the light in post-projective space; behind the camera: the virtual camera's slide ===
      //         (psm.cpp, planLights; the maths in algorithms/psm/psm_plan and psm_camera)
      psm_.planLights(c);
      // ==== 2. the light camera on every object in the (virtual) frustum; its depth pass ===========
      psm_.renderDepth(c);
    });

    // ==== 3. the scene from the eye: each point looked up in the post-projective map ===============
    drawLit(c, technique, {glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0});

    // ==== 4. light 0's map (view=map) ===============================================================
    if (p_.view == View::Map && p_.technique == Technique::Psm && !f.godView) {
      auto t = scope("map view");
      const int side = std::min(f.width, f.height) / 2, x = postView_.rightOfInset(f.width, f.height);
      psm_.drawMaps(0, x, 0, side, side);  // bottom left, beside the post-projective inset: the UI is at the top
      insets.push_back({"map view", x, 0, side, side});
    }

    // ==== 5. the post-projective view: the unit cube, the squashed scene, the light, the slide =====
    postView_.draw(c, technique, insets, legends);
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  Params p_;
  tech::PerspectiveShadowMaps psm_{tech::PsmParams::original()};
  tech::UniformShadowMaps uniform_;
  tech::PostProjectiveView postView_;
};

int main(int argc, char** argv) { return runLesson<OriginalPsmLesson>(argc, argv); }

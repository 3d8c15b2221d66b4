// Lesson 09: Perspective Shadow Maps with every fix of Kozlov et al., "Perspective Shadow Maps: Care
// and Feeding" (GPU Gems 1 ch. 14; the same paper in Russian from IAE SB RAS), each a switch of
// lesson 08's PSM technique (lessons/08_psm/psm.cpp; its maps, one per cube face with fix 3, and
// their depth pass with fix 4's bias in lessons/08_psm/projective_maps.cpp and
// shaders/08_psm/depth_psm.vert, or with impl=student your bias moving the vertices on the CPU in
// cpu_bias_pass.cpp, here; the lookup in shaders/08_psm/shadow_psm.frag), and LiSPSM
// (lispsm.cpp, here) and the uniform map beside it at equal texels:
//   fix.inverse  §3    a light behind the camera gets the inverse projection (Zn = -a, Zf = +a):
//                      a light ray is ordered through infinity, no virtual camera slides back
//   format             16, 24 or 32F bits of depth (the paper: 24 suffice)
//   fix.clip     §4.1  the receivers' rough volumes (a coarse height map, the city's blocks, the
//                      room's walls) clipped by the view frustum: the key points, the smallest cone
//                      from the light holding them, the light camera along it
//   fix.faces    §4.2  the faces of the unit cube the light cannot see, a map each (3 to 5 for a
//                      light outside, 6 inside), when the cone is too wide or always
//   bias=world   §5    a + b L_texel in world space, per caster vertex, against bias=constant
//   technique          lispsm ([Wimmer2004], n_opt) and uniform (lesson 03) on the same controls
// Views: the post-projective view (P: inset, full) with the light, its cone, key points and maps;
// the god view (O) with the receiver volumes, key points and light frusta; view=maps.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the inverse projection, the smallest cone, the face
// test, the texel-size bias, LiSPSM's n_opt; in GLSL (shaders/09_psm_fixes/exercises.glsl) the
// face map a point is looked up in; `--set impl=student` runs yours in the lesson.
#include <numbers>

#include "algorithms/psm/post_shapes.hpp"
#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "core/light_rig.hpp"
#include "cpu_bias_pass.hpp"
#include "exercises.hpp"
#include "lispsm.hpp"
#include "technique/post_projective_view.hpp"
#include "08_psm/psm.hpp"
#include "03_shadow_quality/uniform_maps.hpp"

using namespace shadowlab;

namespace {

enum class Technique { Psm, Lispsm, Uniform };
enum class View { Lit, Visibility, Maps };
constexpr int kLights = 2;

struct Params {
  tech::SceneChoice scene{1, 60000};     // the city: boxes for receivers, sharp shadows near and far
  Technique technique = Technique::Psm;  // PSM with the fixes, LiSPSM, or the uniform map
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your inverse projection, cone, face test, bias and n_opt
  bool equalTexels = true;      // LiSPSM and the uniform map get PSM's texels (map_size)
  float ambient = 0.1f;
  // A sun behind the camera (PSM's hard case: fix 1); a point light (off).
  Light lights[kLights] = {courseSun({-0.5f, -0.45f, -0.7f}), courseLamp({2.0f, 5.0f, -4.0f})};
};

const char* const kSummary =
    "Perspective shadow maps with the paper's four fixes: inverse projection, unit-cube clipping with the "
    "smallest cone, cube-map faces of the unit cube, world-space texel-size bias; against LiSPSM.";
const char* const kHelp =
    R"(fix.inverse (I): fix 1, the inverse projection for a light behind the camera (off: the virtual slide).
fix.clip (C): fix 2, unit-cube clipping: rough receiver volumes, key points, smallest cone.
fix.faces (F): fix 3, never / auto / always the hidden faces of the unit cube. bias (B): constant or world.
format 16 / 24 / 32f. technique (T): PSM, LiSPSM, uniform (equal texels). view.post (P): post-projective view.
view.god (O): volumes, key points, frusta. measure.overlay (M): ground truth. view (V): lit, visibility, maps.)";

// The lesson's exercises as the technique's replaceable steps (impl=student).
psm::Cone studentCone(std::span<glm::dvec3> directions) {
  const glm::dvec4 c = ex09::smallestEnclosingCone({directions.begin(), directions.end()});
  psm::Cone cone;
  const double len = glm::length(glm::dvec3(c));
  cone.valid = len > 0.0 && std::isfinite(len) && c.w >= 0.0 && c.w < std::numbers::pi / 2.0;
  if (cone.valid) cone.axis = glm::dvec3(c) / len;
  cone.halfAngle = c.w;
  return cone;
}

bool studentFaceVisible(int face, const psm::PostProjectiveLight& l) {
  const double w = l.kind == psm::PostLightKind::Direction ? 0.0 : l.kind == psm::PostLightKind::InFront ? 1.0 : -1.0;
  return ex09::cubeFaceVisible(face, w == 0.0 ? glm::dvec4(l.direction, 0.0) : glm::dvec4(l.position, w));
}

}  // namespace

class PsmFixesLesson : public tech::ShadowLesson {
 public:
  PsmFixesLesson() : ShadowLesson("09", /*pathMovesLight=*/true) {}

  void declare(ParamRegistry& r) override {
    camera.aim({0, 2, 0}, 45.0f, 0.5f);  // a city block from above, the sun behind the camera
    camera.nearZ = 1.0f;                 // Zf/Zn = 200: the post-projective cube is not all far face
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what the shadow passes draw");
    r.addChoice("technique", &p_.technique, {"psm", "lispsm", "uniform"},
                "PSM with the fixes (this lesson), LiSPSM, or lesson 03's uniform map, at equal texels")
        .hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "maps"}, "lit, V of the measured light, or light 0's maps")
        .hotkey = "V";
    declareImpl(r, &p_.impl, "whose inverse projection, cone, face test, bias and n_opt the techniques run");
    exercises.add("09.1", "inverseProjection", "fix 1 (fix.inverse) projects with the identity: its shadows are wrong");
    exercises.add("09.2", "smallestEnclosingCone", "fix 2 (fix.clip) gets no cone: its map does not fit the receivers");
    exercises.add("09.3", "cubeFaceVisible", "fix 3 (fix.faces) sees no face of the unit cube: those shadows vanish");
    exercises.add("09.4", "texelSizeBias", "bias=world moves every caster vertex to the origin: its shadows vanish");
    exercises.add("09.5", "lispsmOptimalN", "technique=lispsm gets n = 0: its map is wrong");
    exercises.addGlsl("09.6", "cubeFaceLayer", "fix 3's face maps are never looked up: their shadows vanish");
    r.add("equal_texels", &p_.equalTexels,
          "LiSPSM and the uniform map get the PSM's map_size (a light's total texels)");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    psm_.declare(r, "");  // this lesson's subject: bare names
    for (const auto& [name, key] :
         {std::pair{"fix.inverse", "I"}, {"fix.clip", "C"}, {"fix.faces", "F"}, {"bias", "B"}})
      r.setHotkey(name, key);
    lispsm_.declare(r, "lispsm.");
    uniform_.declare(r, "uniform.");
    postView_.declare(r);
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"09",
            "09_psm_fixes",
            "PSM with the paper's fixes",
            kSummary,
            5,
            kHelp,
            true,
            120,
            {"08"},
            {"light0 light", "light0 maps", "light0 warp's predicted m"}};
  }

  void init() override {
    psm_.init();
    lispsm_.init();
    uniform_.init();
    postView_.init();
    cpuBias_.init();
  }

  void update(const FrameInfo&) override {
    scene_.update(p_.scene);
    if (p_.equalTexels) {  // the same budget: one square map of map_size per light, or its faces
      lispsm_.maps().params().mapSize = psm_.maps().params().mapSize;
      uniform_.params().mapSize = psm_.maps().params().mapSize;
      uniform_.params().cubeSize = psm_.maps().params().mapSize;
    }
    // impl=student: your inverse projection (09.1), cone (09.2), face test (09.3), texel-size bias
    // (09.4) and face choice in the shader (09.6) in PSM, your n_opt (09.5) in LiSPSM.
    tech::PerspectiveShadowMaps::Student psm;
    tech::LightSpacePsm::Student lispsm;
    if (p_.impl == Impl::Student) {
      psm.fixes = {studentCone, ex09::inverseProjection, studentFaceVisible};
      psm.worldBias = cpuBias_.with(ex09::texelSizeBias);  // your bias per vertex, drawn by cpu_bias_pass
      psm.glslFaces = true;
      lispsm.optimalN = ex09::lispsmOptimalN;
    }
    psm_.student = psm;
    lispsm_.student = lispsm;
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c = context(f);
    tech::ShadowTechnique* const techniques[] = {&psm_, &lispsm_, &uniform_};
    tech::ShadowTechnique& technique = *techniques[int(p_.technique)];

    shadowPasses(c, technique, p_.technique == Technique::Psm, [&] {  // (else LiSPSM or lesson 03's map)
      // ==== 1. the plan: the light in post-projective space, receivers' key points, cone or faces ==
      //   fix 1 the inverse projection (algorithms/psm/psm_camera), fix 2 the key points and the
      //   smallest cone (psm/receivers, psm/clipping, psm/enclosing_cone), fix 3 the unit cube's
      //   faces the light cannot see (psm/cube_faces); the whole plan: psm/psm_plan
      psm_.planLights(c);
      // ==== 2. shadow passes: one map, or one per hidden face; casters moved by the world bias =====
      //   fix 4, a + b L_texel per caster vertex (psm/bias, shaders/08_psm/depth_psm.vert; with
      //   impl=student your texelSizeBias on the CPU: cpu_bias_pass.cpp, here)
      psm_.renderDepth(c);
    });

    // ==== 3. the scene from the eye, every light with its map ======================================
    drawLit(c, technique, {glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0});

    // ==== 4. light 0's maps side by side (view=maps) ===============================================
    if (p_.view == View::Maps && !f.godView) {
      auto t = scope("map view");
      // A band along the bottom, beside the post-projective inset (the UI is at the top).
      const int x = postView_.rightOfInset(f.width, f.height), h = f.height / 3;
      const int w = p_.technique == Technique::Psm ? std::min(f.width - x, h * 6) : h;
      if (p_.technique == Technique::Psm) psm_.drawMaps(0, x, 0, w, h);
      if (p_.technique == Technique::Lispsm) lispsm_.drawMaps(0, x, 0, w, h);
      if (p_.technique != Technique::Uniform) insets.push_back({"map view", x, 0, w, h});
    }

    // ==== 5. the post-projective view: the unit cube, the light there, its cone, maps, key points ==
    postView_.draw(c, technique, insets, legends);
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  Params p_;
  tech::PerspectiveShadowMaps psm_;
  tech::LightSpacePsm lispsm_;
  tech::UniformShadowMaps uniform_;
  tech::PostProjectiveView postView_;
  tech::CpuBiasPass cpuBias_;  // fix 4 on the CPU: the depth pass of your texelSizeBias (impl=student)
};

int main(int argc, char** argv) { return runLesson<PsmFixesLesson>(argc, argv); }

// Lesson 03: shadow-map quality ([Kozlov2004] §2, [Boreskov2005], [Tarantsev-L12]). Everything
// that makes lesson 02's maps good, each a switch, in the uniform shadow-map technique
// (lessons/03_shadow_quality/uniform_maps.cpp and shaders/03_shadow_quality/shadow_uniform.frag, which this lesson is
// about):
//   bias      constant, slope-scaled (polygon offset and in the shader), normal offset, receiver
//             plane, front-face culling in the depth pass
//   texels    resolution 256..8192; filtering nearest, hardware 2x2 PCF, N x N PCF, Poisson disk
//   fitting   a directional light whose orthographic frustum covers only the receivers the view
//             needs and the casters that can shade them (the light volume swept from the view
//             frustum toward the light); casters outside are not drawn; texel snapping
//   lights    a point light with a cube map (faces the view cannot see are skipped), a spot light,
//             all at once, each with its own map (the course's light rig: light0..light2)
//   against   technique=volumes: lesson 04's stencil shadow volumes on the same scene (the A/B
//             split shows one on each side, each with its ground-truth figures)
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): slope-scaled bias, PCF weights, cube face selection, the caster
// culling test, the orthographic fit; in GLSL (shaders/03_shadow_quality/exercises.glsl) the
// N x N PCF kernel.
#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "core/light_rig.hpp"
#include "core/scene_gen.hpp"
#include "exercises.hpp"
#include "technique/map_view.hpp"
#include "technique/no_shadows.hpp"
#include "04_shadow_volumes/stencil_volumes.hpp"
#include "uniform_maps.hpp"

using namespace shadowlab;

namespace {

enum class Technique { Uniform, Volumes, None };
enum class View { Lit, Visibility, SunMap };
constexpr int kLights = 3;

struct Params {
  tech::SceneChoice scene{1, 60000};         // city: long straight edges show acne, aliasing and shimmer
  Technique technique = Technique::Uniform;  // the uniform maps, lesson 04's volumes, or none (V = 1)
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your culling test and fit drive the directional light's pass
  bool drift = false;           // move the camera slowly (shows shimmer without snapping)
  float ambient = 0.1f;
  // The sun on; a warm point light with a cube map and a blue spot with a 2D map, off.
  Light lights[kLights] = {courseSun({-0.45f, -1.0f, -0.3f}), courseLamp({4.0f, 6.0f, 3.0f}), citySpot()};
};

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Bias family, resolution, PCF family, a directional light fitted to the view with caster culling and "
    "texel snapping, cube maps, several lights.";
const char* const kHelp =
    R"(Bias: the bias.* sliders, cull_front (B), bias.normal_offset (N: 0 <-> default), bias.receiver_plane (Y).
Filtering: filter (P) cycles nearest, hardware 2x2, N x N, Poisson; map_size 256..8192.
Fit: fit (F) scene or view; cull_casters (K): culled casters in the header; snap (U) with
drift (G): shimmer without snapping. light0..light2 (1 2 3): sun, point (cube map), spot.
technique (T): stencil volumes on the same scene. measure.overlay (M): error and aliasing; view.god (O).)";

}  // namespace

// The lesson holds two techniques and draws with the one `technique` picks; the uniform maps'
// parameters keep their bare names, the volumes' get the prefix volumes.
class ShadowQualityLesson : public tech::ShadowLesson {
 public:
  ShadowQualityLesson() : ShadowLesson("03") {}

  void declare(ParamRegistry& r) override {
    camera.aim({0, 2, 0}, 45.0f, 0.5f);  // a city block from above: long shadows across streets
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what the shadow passes draw");
    r.addChoice("technique", &p_.technique, {"uniform", "volumes", "none"},
                "uniform shadow maps (this lesson), lesson 04's stencil volumes on the same scene, or none (V = 1)")
        .hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "sun_map"}, "lit, V of the measured light, or light 0's map")
        .hotkey = "V";
    declareImpl(r, &p_.impl, "whose caster-culling test and orthographic fit drive the directional light's pass");
    exercises.add("03.1", "slopeScaledBias", "");  // "": not used live, so no banner
    exercises.add("03.2", "bilinearPcfWeights", "");
    exercises.add("03.3", "cubeFace", "");
    exercises.add("03.4", "casterMayShadow", "every caster is kept: the same picture at the full cost");
    exercises.add("03.5", "fitOrthographic", "the sun's map covers nothing: its shadows are gone or wrong");
    exercises.addGlsl("03.6", "pcfKernel", "filter=pcf_nxn lights every pixel of the 2D maps: no shadows",
                      "filter=pcf_nxn");
    r.add("drift", &p_.drift, "move the camera slowly along x (watch edges shimmer without snapping)").hotkey = "G";
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    maps_.declare(r, "");  // this lesson's subject: its parameters keep their bare names
    for (const auto& [name, key] : {std::pair{"filter", "P"},
                                    {"bias.normal_offset", "N"},
                                    {"bias.receiver_plane", "Y"},
                                    {"cull_front", "B"},
                                    {"fit", "F"},
                                    {"snap", "U"},
                                    {"cull_casters", "K"}})
      r.setHotkey(name, key);
    volumes_.declare(r, "volumes.");
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"03",
            "03_shadow_quality",
            "Shadow-map quality",
            kSummary,
            3,
            kHelp,
            true,
            120,
            {"02"},
            {"light0 texel", "culled casters", "cube faces skipped"}};
  }

  void init() override {
    maps_.init();
    volumes_.init();
    mapView_.build();
  }

  void update(const FrameInfo& f) override {
    scene_.update(p_.scene);
    if (p_.drift) camera.target.x += float(f.dt) * 0.37f;
    // impl=student: your culling test (03.4), fit (03.5) and N x N kernel (03.6, filter=pcf_nxn).
    maps_.student = p_.impl == Impl::Student
                        ? tech::UniformShadowMaps::Student{ex03::casterMayShadow, ex03::fitOrthographic, true}
                        : tech::UniformShadowMaps::Student{};
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c = context(f);
    tech::ShadowTechnique* const techniques[] = {&maps_, &volumes_, &none_};
    tech::ShadowTechnique& technique = *techniques[int(p_.technique)];

    shadowPasses(c, technique, p_.technique == Technique::Uniform, [&] {  // (else 04's volumes or none)
      // ==== 1. the light cameras: fit, cull casters, skip cube faces (algorithms/light_cameras) ===
      maps_.fitLights(c);
      // ==== 2. shadow passes: polygon offset; one map per directional or spot light, six faces ====
      //         per point light (uniform_maps.cpp, renderDepth)
      maps_.renderDepth(c);
    });

    // ==== 3. the scene from the eye, every light with its map ====================================
    drawLit(c, technique, {glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0});

    // ==== 4. light 0's map as an image (view=sun_map) =============================================
    if (p_.view == View::SunMap && maps_.map2D(0) && technique.name() == "uniform") {
      auto t = scope("map view");
      const int side = std::min(f.width, f.height);
      mapView_.draw(*maps_.map2D(0), (f.width - side) / 2, 0, side, side, std::nullopt);
    }
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  Params p_;
  tech::UniformShadowMaps maps_;
  tech::StencilVolumes volumes_;
  tech::NoShadows none_;
  tech::DepthMapView mapView_;
};

int main(int argc, char** argv) { return runLesson<ShadowQualityLesson>(argc, argv); }

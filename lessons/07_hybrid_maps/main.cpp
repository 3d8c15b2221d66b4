// Lesson 07: hybrid-resolution shadow maps (Li, Yang, Zhao, Chen, "Hybrid-resolution shadow
// mapping design and hard shadows anti-aliasing in special effects movies", Chinese Optics 9(1),
// 2016). A standard map spends the same texels on a flat street as on a tower's silhouette. The
// paper renders the full map, then sweeps it bottom-up: every 2x2 block whose depths agree
// becomes one texel of their mean, for one to three levels, and an index records where the
// kept texels are; the lookup follows the index down to the finest texel stored. The technique
// (lessons/07_hybrid_maps/hybrid_maps, its GPU passes in hybrid_build, its GLSL in
// shaders/07_hybrid_maps/shadow_hybrid.frag) is this lesson's subject; its GL-free reference is
// common/algorithms/hybrid_map. Against it: lesson 03's uniform map (technique=standard).
//   criterion  what the merge test reads: window depth (the paper's |m - Dn| / Dn <= eps0),
//              linear depth, or the depth's derivative (a slope bound)
//   levels     0 (a standard map) to 3 sweeps; eps0 and max_slope the thresholds
//   views      the map coloured by level over the light's view, the merge mask on the scene, the
//              steps each lookup took, and the memory against the full map in the header
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the merge criterion, one level of the sweep, the index descent,
// linear depth.
#include <cstdio>

#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "core/light_rig.hpp"
#include "exercises.hpp"
#include "hybrid_maps.hpp"
#include "03_shadow_quality/uniform_maps.hpp"

using namespace shadowlab;

namespace {

enum class Technique { Hybrid, Standard };
enum class View { Lit, Visibility, Levels, Mask, Steps };
constexpr int kLights = 2;

struct Params {
  tech::SceneChoice scene{1, 60000};        // city: flat streets and roofs merge, tower silhouettes must not
  Technique technique = Technique::Hybrid;  // the hybrid map, or lesson 03's uniform map (uniform.*)
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your sweep (07.1, 07.2) builds the sun's map on the CPU
  float ambient = 0.1f;
  float bandTexels = 2.0f;  // measured "near an edge": within this many source texels of a shadow boundary
  int bandMapSize = 0;      // ... texels of a map this size (0: the technique's own), so that maps of any
                            // size can be judged on the same pixels
  // The sun over the city; a spot (off) for the depth spaces of a perspective map, whose window
  // depth crowds toward 1.
  Light lights[kLights] = {courseSun({-0.45f, -1.0f, -0.3f}), cityHighSpot()};
};

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Hybrid-resolution shadow maps: a full map merged bottom-up where its depth is smooth, an index to "
    "the kept texels; the paper's claims measured.";
const char* const kHelp = R"(The map merges 2x2 blocks whose depths agree: levels (L) (0 = a standard map),
eps0 and max_slope thresholds, criterion (C): window depth as the paper, linear, slope.
view (V): lit, visibility, levels (the map by level), mask (the scene by level), steps.
The header: stored texels and bytes (root + index) against the full map.
technique (T): lesson 03's uniform map (uniform.*). build (G): on the CPU (the reference).
measure.overlay (M): error and aliasing heatmaps; the figures near edges are in --measure's JSON.)";

// Exercise 07.2 as the technique's sweep step.
hybrid::MergeGrid studentSweep(const hybrid::MergeGrid& children, const hybrid::MergeRule& rule, int) {
  return ex07::sweepLevel(children, rule.eps0);
}

}  // namespace

// The lesson holds the hybrid maps (its subject: bare parameter names) and lesson 03's uniform
// maps (prefix uniform.) to compare with, and tells the hybrid map's passes one by one.
class HybridMapsLesson : public tech::ShadowLesson {
 public:
  HybridMapsLesson() : ShadowLesson("07") {}

  void declare(ParamRegistry& r) override {
    camera.aim({0, 2, 0}, 45.0f, 0.5f);  // the city from above: long shadows across the streets
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what the depth pass draws");
    r.addChoice("technique", &p_.technique, {"hybrid", "standard"},
                "the hybrid map (this lesson) or lesson 03's uniform map at its own size (uniform.*)")
        .hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "levels", "mask", "steps"},
                "lit; V of the measured light; the map by level; the scene by level; steps per lookup")
        .hotkey = "V";
    declareImpl(r, &p_.impl, "whose merge sweep (07.1, 07.2) builds the maps (yours runs on the CPU)");
    exercises.add("07.1", "mergeBlock: the merge criterion", "");  // "": not used live, so no banner
    exercises.add("07.2", "sweepLevel: one level of the sweep", "the lesson stops: the sweep returns a 0x0 grid");
    exercises.add("07.3", "descend: the index descent", "");
    exercises.add("07.4", "linearDepth", "");
    exercises.addGlsl("07.5", "hybridDescend: the index descent", "every tap reads depth 1.0: no shadows");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    r.add("edge_band.texels", &p_.bandTexels, 0.5f, 16, "measured near an edge: within this many texels of a boundary");
    r.add("edge_band.map_size", &p_.bandMapSize, 0, 8192,
          "the map whose texels edge_band.texels counts (0: the technique's own): judge maps of any size on the same "
          "pixels");
    hybrid_.declare(r, "");  // this lesson's subject: its parameters keep their bare names
    for (const auto& [name, key] : {std::pair{"levels", "L"}, {"criterion", "C"}, {"filter", "P"}, {"build", "G"}})
      r.setHotkey(name, key);
    standard_.declare(r, "uniform.");
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"07", "07_hybrid_maps", "Hybrid-resolution shadow maps",           kSummary, 4, kHelp, true,
            90,   {"03"},           {"light0 stored texels", "light0 records"}};
  }

  void init() override {
    hybrid_.init();
    standard_.init();
  }

  MeasureSource measureSource() override {
    MeasureSource m = ShadowLesson::measureSource();
    m.edgeBand = edgeBand();
    return m;
  }

  void update(const FrameInfo&) override {
    scene_.update(p_.scene);
    // impl=student: your level sweep (07.2: window depth, eps0; the maps then build on the CPU) and
    // your index descent at every tap (07.5).
    hybrid_.student = p_.impl == Impl::Student ? tech::HybridShadowMaps::Student{studentSweep, true}
                                               : tech::HybridShadowMaps::Student{};
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c = context(f);
    if (f.measureLight >= 0 && f.measureLight < kLights) measured_ = f.measureLight;
    tech::ShadowTechnique& technique = p_.technique == Technique::Standard
                                           ? static_cast<tech::ShadowTechnique&>(standard_)
                                           : static_cast<tech::ShadowTechnique&>(hybrid_);
    shadowPasses(c, technique, p_.technique == Technique::Hybrid, [&] {  // (else lesson 03's passes)
      // ==== 1. the light camera: fitted to the view as lesson 03 fits its sun ====================
      hybrid_.fitLights(c);
      // ==== 2. the full-resolution depth map: what a standard map of map_size renders ============
      hybrid_.renderDepth(c);
      // ==== 3. the merge sweep: 2x2 blocks whose depths agree become one texel, level by level ==
      // ==== 4. the index: the root grid and a record of four words for every kept texel =========
      hybrid_.buildMaps(c);
    });

    // ==== 5. the scene from the eye: each lookup descends the index to the finest stored texel ====
    const tech::LitSettings lit{glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0};
    const bool hybrid = p_.technique == Technique::Hybrid;
    const int shown = hybrid_.viewLight(measured_);  // the views: the measured light, or the first mapped
    if (hybrid && (p_.view == View::Mask || p_.view == View::Steps)) {
      auto t = scope("scene");
      glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      hybrid_.drawSceneView(c, p_.view == View::Mask ? tech::HybridSceneView::Levels : tech::HybridSceneView::Steps,
                            lit, shown);
    } else {
      drawLit(c, technique, lit);
    }

    // ==== 6. the map itself, coloured by level over the light's view (view=levels) ==============
    if (hybrid && p_.view == View::Levels) {
      const int side = std::min(f.width, f.height);
      hybrid_.drawLevels(shown, (f.width - side) / 2, 0, side, side);
    }
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  // "Near an edge" for the measurement: edge_band.texels texels of the band's map, across the measured
  // light, from whichever technique's light camera: a width in world units (the sun's orthographic
  // map) or at unit distance (a spot's perspective one).
  float edgeBand() {
    const shadow::LightCamera* cam = nullptr;
    bool perspective = p_.lights[measured_].kind != LightKind::Directional;
    if (p_.technique == Technique::Hybrid && hybrid_.camera(measured_)) cam = &hybrid_.camera(measured_)->camera;
    if (p_.technique == Technique::Standard) cam = standard_.camera(measured_);
    if (!cam) return 0.0f;
    const float width = perspective ? 2.0f / cam->projection[1][1] : 2.0f / cam->projection[0][0];
    const int own = p_.technique == Technique::Standard ? standard_.params().mapSize : hybrid_.params().mapSize;
    const int texels = p_.bandMapSize > 0 ? p_.bandMapSize : own;
    return p_.bandTexels * width / float(texels);
  }

  // The spot's near plane further out than lesson 03's: window depth keeps precision where the city is.
  static tech::HybridMapParams hybridDefaults() {
    tech::HybridMapParams d;
    d.spotNear = 5.0f;
    return d;
  }
  static tech::UniformMapParams standardDefaults() {
    tech::UniformMapParams d;
    d.spotNear = 5.0f;
    return d;
  }

  Params p_;
  int measured_ = 0;  // the light the measurement judges (the last frame that measured)
  tech::HybridShadowMaps hybrid_{hybridDefaults()};
  tech::UniformShadowMaps standard_{standardDefaults()};
};

int main(int argc, char** argv) { return runLesson<HybridMapsLesson>(argc, argv); }

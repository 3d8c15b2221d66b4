// Lesson 05: soft shadows (Tarantsev's lecture 12, after Rogers: many point lights, the spherical
// light's penumbra, A_frac, single-sample soft shadows, the light mesh; and what engines ship:
// PCF, PCSS, filterable maps). A spherical light of radius R (light0.area = sphere,
// light0.radius); every approximation is a technique in this folder, each measured against
// the Embree sphere-light reference (M, --measure):
//   many    N point lights on the sphere, one map each, averaged         (many_lights.cpp)
//   pcf     one map from the centre, a fixed Poisson kernel: the baseline (pcss.cpp)
//   pcss    blocker search, w = (d_r - d_b) / d_b * R, filter: contact hardening (pcss.cpp)
//   parker  [Parker1998]: the hard shadow as umbra, an outer hull  (single_sample.cpp)
//   haines  [Haines2001]: plateaus on the ground plane                    (single_sample.cpp)
//   mesh    the light mesh: visibility baked on a 3D grid, trilinear     (light_mesh.cpp)
//   vsm esm filterable maps with a blur; VSM's light bleeding            (filterable_maps.cpp)
//   evsm2 evsm4 msm  exponential variance and moment shadow maps: less bleeding (the same file;
//           their bounds in common/algorithms/moment_maps)
// and the theory drawn live (soft_theory.cpp): the predicted inner and outer penumbra edges
// r = d / (n.L) * R / D of a caster edge the lecturer picks (E), A_frac against (1 + a/R) / 2.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the half-width, A_frac and its line, the PCSS radius, tap
// rotation, the light mesh's trilinear average.
#include <imgui.h>

#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "core/light_rig.hpp"
#include "exercises.hpp"
#include "pcss.hpp"
#include "soft_techniques.hpp"
#include "soft_theory.hpp"

using namespace shadowlab;

namespace {

enum class View { Lit, Visibility };
constexpr int kLights = 2;
constexpr int kEdgeSamples = 25;  // odd: the middle sample is the edge's midpoint

struct Params {
  tech::SceneChoice scene{0, 30000};  // showcase: contact penumbras at the box, far ones under the knot
  int technique = 0;  // which of soft_techniques.cpp's list: declare() starts at pcss, the one engines ship
  View view = View::Lit;
  Impl impl = Impl::Reference;  // student: your half-width draws the edges, your A_frac the plot
  float ambient = 0.12f;
  bool showEdge = false;  // the predicted penumbra of the picked caster edge
  int edge = 11;          // which of the box's 12 edges (soft::boxEdges): 11 is a top edge over open ground
  bool plot = false;      // A_frac against its linear approximation (ImGui; P, or the afrac_linear preset)
  // A sphere of radius 0.5 m over the showcase, a spot whose cone holds the scene's shapes; a second
  // sphere (off), to show that every technique serves several lights.
  Light lights[kLights] = {showcaseSphereSpot(), secondSphereSpot()};
};

const char* const kSummary =
    "A spherical light: many point lights, PCF and PCSS, single-sample soft shadows, the light mesh, VSM, ESM, EVSM "
    "and MSM, "
    "each against the sphere-light reference; the penumbra formula and A_frac drawn live.";
const char* const kHelp =
    R"(technique (T): many lights, PCF, PCSS, Parker, Haines, light mesh, VSM, ESM, EVSM 2 and 4, MSM.
light0.radius: the sphere's size (0: hard). many.samples: N maps. pcss.* taps.
theory.edges (G): the predicted penumbra of the box edge theory.edge (N) (yellow centre, red inner, cyan outer).
theory.plot (P): the A_frac plot; parker.profile (L): exact or linear (the 7 %; haines.profile too).
view (V): the visibility alone. measure.overlay (M): error against the sphere-light reference; view.god (O).)";

}  // namespace

// The lesson holds every soft technique and draws with the one `technique` picks; each declares its
// parameters under its own name (many.samples, pcss.filter_taps, ...), so the showdown can hold
// them the same way.
class SoftShadowsLesson : public tech::ShadowLesson {
 public:
  SoftShadowsLesson() : ShadowLesson("05", /*pathMovesLight=*/true) {}

  void declare(ParamRegistry& r) override {
    camera.aim({-3.5f, 0.0f, -0.5f}, 15.0f, 0.9f);  // from above: the box's long shadow, the knot's far one
    camera.yaw = -0.3f;
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what every shadow pass draws");
    p_.technique = techniques_.indexOf("pcss");
    r.addChoice("technique", &p_.technique, techniques_.names(),
                "which approximation of the sphere's visible fraction draws the shadows")
        .hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility"}, "lit, or V of the measured light alone").hotkey = "V";
    declareImpl(r, &p_.impl, "whose half-width draws the predicted edges, whose A_frac the plot");
    exercises.add("05.1", "penumbraHalfWidth", "the predicted penumbra edges collapse onto the hard shadow's edge");
    exercises.add("05.2", "visibleFraction, visibleFractionLinear", "the A_frac plot is a flat line at 1/2");
    exercises.add("05.3", "pcssFilterRadiusUv", "");  // "": not used live, so no banner
    exercises.add("05.4", "rotateTap", "");
    exercises.add("05.5", "lightMeshVisibility", "");
    exercises.addGlsl("05.6", "blockerSearch", "technique=pcss finds no blocker: no shadows", "technique=pcss");
    exercises.add("05.7", "msmLitShare", "");  // technique=msm's bound, graded on its own
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    r.add("theory.edges", &p_.showEdge, "draw the lecture's predicted penumbra of the picked caster edge").hotkey = "G";
    r.addChoice("theory.edge", &p_.edge, {"0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11"},
                "which edge of the box (0-3 along its x, 4-7 upright, 8-11 along its z)")
        .hotkey = "N";
    r.add("theory.plot", &p_.plot, "A_frac against (1 + a/R) / 2, with the largest difference").hotkey = "P";
    techniques_.declare(r);  // each under its own name: many.samples, pcss.filter_taps, ...
    r.setHotkey("parker.profile", "L");
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    return {"05",
            "05_soft_shadows",
            "Soft shadows",
            kSummary,
            4,
            kHelp,
            true,
            120,
            {"03"},
            {"taps", "penumbra r predicted", "light0", "light1"}};  // lightN: a cube, or no soft shadow and why
  }

  void init() override {
    techniques_.init();
    edgeLines_.build();
  }

  void update(const FrameInfo&) override {
    scene_.update(p_.scene);
    techniques_.get<tech::PcssShadows>("pcss").student.glslSearch = p_.impl == Impl::Student;  // 05.6
  }

  void render(const FrameInfo& f) override {
    const tech::ShadowContext c = context(f);
    tech::ShadowTechnique& technique = techniques_[p_.technique];

    // ==== 1. the light cameras: at the sphere's centre, or at each of N points on it =============
    // ==== 2. shadow passes (maps, moments and their blur, or the light mesh's bake) ==============
    technique.renderShadows(c);
    if (!f.godView) {
      counters = technique.stats().counters();
      addTheoryCounters();
    }

    // ==== 3. the scene from the eye, V from the technique ========================================
    drawLit(c, technique, {glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0});

    // ==== 4. the theory over it: the predicted penumbra of the picked edge =======================
    if (p_.showEdge) {
      auto t = scope("theory");
      const auto [a, b] = pickedEdge();
      const auto lines = tech::penumbraLines(a, b, predictedPenumbra());
      withoutMeasurement(
          [&] { edgeLines_.draw(lines, f.projection * f.view, false, LineRenderer::projectorWidth(f.height)); });
    }
  }

  void gui() override {
    if (!p_.plot || panelsHidden) return;
    const bool student = p_.impl == Impl::Student;
    tech::visibleFractionPlot(student ? tech::FractionFn(ex05::visibleFraction) : soft::visibleFraction,
                              student ? tech::FractionFn(ex05::visibleFractionLinear) : soft::visibleFractionLinear);
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  // The box's edge the overlay follows, and a point inside the box (its shadow is the umbra side).
  std::array<glm::vec3, 2> pickedEdge() const {
    for (const SceneObject& o : scene_.scene().objects)
      if (o.name == "box") return soft::boxEdges(o.model, glm::vec3(1.0f))[std::size_t(p_.edge)];
    return {glm::vec3(0.0f), glm::vec3(0.0f)};
  }
  glm::vec3 boxCentre() const {
    for (const SceneObject& o : scene_.scene().objects)
      if (o.name == "box") return glm::vec3(o.model[3]);
    return glm::vec3(0.0f);
  }

  // The lecture's prediction along the edge, over the ground plane y = 0, from light0's centre.
  std::vector<soft::PenumbraEdgeSample> predictedPenumbra() const {
    const Light& l = p_.lights[0];
    const auto [a, b] = pickedEdge();
    const soft::HalfWidthFn student = ex05::penumbraHalfWidth;
    return soft::penumbraAlongEdge(l.position, l.area == AreaShape::Sphere ? l.radius : 0.0f, a, b, boxCentre(),
                                   {0, 1, 0, 0}, kEdgeSamples, p_.impl == Impl::Student ? student : nullptr);
  }

  // The figures the overlays show, in the header (and in --measure's counters).
  void addTheoryCounters() {
    const auto samples = predictedPenumbra();
    char buf[128];
    if (!samples.empty()) {
      const auto& mid = samples[samples.size() / 2];
      std::snprintf(buf, sizeof buf, "%.4f m at the middle (edge %d), %.4f .. %.4f along it", mid.halfWidth, p_.edge,
                    samples.front().halfWidth, samples.back().halfWidth);
      counters.push_back({"penumbra r predicted", buf});
    }
    const bool student = p_.impl == Impl::Student;
    const tech::PlotFigures f =
        tech::compareFractions(student ? tech::FractionFn(ex05::visibleFraction) : soft::visibleFraction,
                               student ? tech::FractionFn(ex05::visibleFractionLinear) : soft::visibleFractionLinear);
    std::snprintf(buf, sizeof buf, "%.2f %% at a/R = %+.3f", 100.0f * f.maxDifference, f.at);
    counters.push_back({"A_frac linear error", buf});
  }

  Params p_;
  tech::TechniqueSet techniques_{tech::softTechniques()};
  LineRenderer edgeLines_{"05 penumbra edges"};
};

int main(int argc, char** argv) { return runLesson<SoftShadowsLesson>(argc, argv); }

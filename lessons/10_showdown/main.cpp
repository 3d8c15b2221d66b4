// Lesson 10: the showdown. Every shadow technique of the course in one program, on the same scene,
// camera and lights, each the technique of the lesson that teaches it (lessons/NN_name), so that the question
// of the course can be asked with figures: which technique when?
//   hard      uniform (lesson 03's fitted maps), psm (lesson 09: PSM with the fixes), lispsm,
//             csm (cascaded shadow maps: practical splits, blend band, texel snapping per cascade),
//             sdsm (the cascades split over the depths on screen, each fitted to its samples),
//             hybrid (lesson 07's hybrid-resolution maps), volumes (lesson 04's stencil volumes)
//   soft      lesson 05's many, pcf, pcss, parker, haines, mesh, vsm, esm, evsm2, evsm4, msm (they need a spherical
//             light: the soft_* presets switch the sun off and light1, lesson 05's sphere, on)
// all at EQUAL TOTAL TEXELS (texels: a light's budget, whatever the technique spends it on: one
// map, a face set, four cascades). Views: one technique lit; the A/B split (X) between any two
// (ab.preset picks B among the presets, one per technique); the four-up view, each quarter a
// technique on the same camera with its figures; the god view (O) and the post-projective view (P)
// of the selected one; csm.colours (C) colours each point by its cascade.
// tools/showdown_bench.sh measures them all over camera paths and light directions: time against
// error per scene, the Pareto front, and the "which technique when" summary (README).
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): the practical split scheme, texel snapping, the cascade for a depth
// with its blend band; in GLSL (shaders/10_showdown/exercises.glsl) the same choice in the shader;
// `--set impl=student` runs your split scheme, snapping and shader choice in technique=csm.
#include <chrono>
#include <cstdio>

#include <imgui.h>

#include "app/lesson.hpp"
#include "technique/shadow_lesson.hpp"
#include "exercises.hpp"
#include "core/light_rig.hpp"
#include "gl/gl.hpp"
#include "03_shadow_quality/uniform_maps.hpp"
#include "07_hybrid_maps/hybrid_maps.hpp"
#include "08_psm/psm.hpp"
#include "09_psm_fixes/lispsm.hpp"
#include "cascades.hpp"
#include "showdown_techniques.hpp"
#include "technique/post_projective_view.hpp"

using namespace shadowlab;

namespace {

enum class View { Lit, Visibility, Maps, FourUp };
constexpr int kLights = 2;

struct Params {
  tech::SceneChoice scene{1, 60000};  // the city: long straight edges near and far, the light's hard case
  int technique = 0;                  // of showdown_techniques.cpp's list: declare() starts at csm, the baseline
  View view = View::Lit;
  bool equalTexels = true;  // every map technique gets `texels` squared per light
  int texels = 2048;        // 2048^2 per light (texels per side, one of tech::kMapSizes)
  int quarter[4] = {};      // the four-up view: declare() starts at uniform, psm, lispsm, csm
  float ambient = 0.1f;
  Impl impl = Impl::Reference;  // student: your split scheme and texel snapping drive technique=csm
  // Lesson 09's sun over the city, behind the camera; lesson 05's spherical spot over the showcase
  // (off): the light the soft_* presets switch to.
  Light lights[kLights] = {courseSun({-0.5f, -0.45f, -0.7f}), off(showcaseSphereSpot())};
};

const char* const kSummary =
    "Every technique of the course on one scene at equal texels: uniform, PSM, LiSPSM, cascades, hybrid, "
    "volumes and the soft methods; the A/B split, a four-up view, and the benchmark's time against error.";
const char* const kHelp = R"(technique (T): uniform, psm, lispsm, csm, sdsm, hybrid, volumes, the soft ones, none.
texels: each light's total budget, shared by a technique's maps (equal_texels (U): on or off).
view (V): lit, visibility, the maps, four-up (quarter.0..3 pick the four). csm.colours (C): cascade colours.
ab.enabled (X): the A/B split against ab.preset (one preset per technique). view.god (O), view.post (P).
Soft methods need a spherical light: a soft_* preset turns light1 (a sphere) on. measure.overlay (M): ground truth.)";

// One quarter of the four-up view: its own target, its technique's figures, a smoothed wall time.
struct Quarter {
  gl::RenderTarget target;
  double ms = 0.0;
  std::string label;
};

}  // namespace

// The lesson holds every technique under its own prefix (uniform.map_size, csm.cascades, ...) and
// draws with the selected one, or with four of them side by side.
class ShowdownLesson : public tech::ShadowLesson {
 public:
  ShowdownLesson() : ShadowLesson("10", /*pathMovesLight=*/true) {}

  void declare(ParamRegistry& r) override {
    camera.aim({0, 2, 0}, 45.0f, 0.5f);  // the city from above (lesson 09's view): near and far shadows
    camera.nearZ = 1.0f;                 // Zf/Zn = 200, as lesson 09 (PSM's unit cube is not all far face)
    tech::SceneCache::declare(r, &p_.scene, "procedural scene", "scene size: what every shadow pass draws");
    const std::vector<std::string> names = techniques_.names();
    p_.technique = techniques_.indexOf("csm");
    for (int q = 0; q < 4; ++q) p_.quarter[q] = techniques_.indexOf(std::array{"uniform", "psm", "lispsm", "csm"}[q]);
    r.addChoice("technique", &p_.technique, names, "which technique draws the shadows").hotkey = "T";
    r.addChoice("view", &p_.view, {"lit", "visibility", "maps", "four_up"},
                "lit, V of the measured light, light 0's maps, or four techniques side by side")
        .hotkey = "V";
    r.add("equal_texels", &p_.equalTexels, "every map technique gets `texels` squared per light").hotkey = "U";
    tech::declareMapSize(
        r, "texels", &p_.texels,
        "a light's total texel budget (side of the square): one map, a face set or the cascades share it");
    for (int q = 0; q < 4; ++q)
      r.addChoice("quarter." + std::to_string(q), &p_.quarter[q], names,
                  "the four-up view's technique in quarter " + std::to_string(q) + " (top left, top right, ...)");
    r.add("ambient", &p_.ambient, 0, 1, "ka Ia");
    declareImpl(r, &p_.impl, "whose split scheme and texel snapping the cascades (technique=csm) run");
    exercises.add("10.1", "practicalSplits", "technique=csm gets no splits: the sun's cascades are gone (lit)");
    exercises.add("10.2", "snapToTexels", "csm.snap=on: each cascade's map covers nothing: its shadows are gone");
    exercises.add("10.3", "cascadeAt", "");  // "": the lit shader picks the cascade (10.4); not used live
    exercises.addGlsl("10.4", "cascadeAt", "technique=csm: no point falls in a cascade: the sun casts no shadow",
                      "technique=csm");
    techniques_.declare(r);  // each under its own name: uniform.map_size, csm.cascades, ...
    r.setHotkey("csm.colours", "C");
    postView_.declare(r);
    declareLights(r, p_.lights);
  }

  LessonInfo info() const override {
    LessonInfo i{"10", "10_showdown", "The showdown: every technique, time against error", kSummary, 5, kHelp, true};
    i.minutes = 90;
    i.prerequisites = {"04", "05", "07", "09"};
    i.keyFigures = {"light0 light", "light0 maps", "light0 splits", "light0 depth range", "light0 cascade texels"};
    return i;
  }

  void init() override {
    techniques_.init();
    postView_.init();
  }

  void update(const FrameInfo&) override {
    scene_.update(p_.scene);
    if (p_.equalTexels) equaliseTexels();
    // impl=student: your split scheme (10.1), texel snapping (10.2) and cascade choice in the shader (10.4).
    csm_.student = p_.impl == Impl::Student
                       ? tech::CascadedShadowMaps::Student{ex10::practicalSplits, ex10::snapToTexels, true}
                       : tech::CascadedShadowMaps::Student{};
  }

  void render(const FrameInfo& f) override {
    tech::ShadowTechnique& technique = techniques_[p_.technique];
    if (p_.view == View::FourUp) {
      renderFourUp(f);
      return;
    }
    // ==== 1. the selected technique: its light cameras and shadow passes (or volumes) ==============
    const tech::ShadowContext c = context(f);
    technique.renderShadows(c);
    if (!f.godView) counters = technique.stats().counters();
    // ==== 2. the scene from the eye, V from the technique ==========================================
    drawLit(c, technique, litSettings());
    // ==== 3. light 0's maps (view=maps), the post-projective view ==================================
    if (p_.view == View::Maps && !f.godView) drawMaps(f);
    postView_.draw(c, technique, insets, legends);
  }

  // The four-up view shows four techniques in one frame: one ground truth cannot judge it.
  MeasureSource measureSource() override {
    MeasureSource s = ShadowLesson::measureSource();
    if (p_.view != View::FourUp) return s;
    std::string quarters;
    for (int q = 0; q < 4; ++q) quarters += (q ? ", " : "") + techniques_[p_.quarter[q]].name();
    s.unmeasurable =
        "not in the four-up view (four techniques in one frame): measure one at a time with view=lit "
        "and technique= one of " +
        quarters;
    return s;
  }

  // Each quarter's label in its corner by the screen's middle line (top row: bottom right; bottom
  // row: top right), wrapped to the quarter's width, so the labels never run into each other and stay
  // clear of the header (top left), the panel (top right) and the exercises (bottom left); small
  // windows, so --ui-layout reports them ("quarter N label").
  void gui() override {
    if (p_.view != View::FourUp) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoNav;
    for (int q = 0; q < 4; ++q) {
      const bool top = q < 2;
      const ImVec2 corner((q % 2 + 1) * size.x * 0.5f - 6.0f, size.y * 0.5f + (top ? -6.0f : 6.0f));
      ImGui::SetNextWindowPos(corner, ImGuiCond_Always, ImVec2(1, top ? 1.0f : 0.0f));
      ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(size.x * 0.5f - 12.0f, size.y * 0.5f));
      ImGui::SetNextWindowBgAlpha(0.7f);
      ImGui::Begin(("quarter " + std::to_string(q) + " label").c_str(), nullptr, flags);
      ImGui::PushTextWrapPos(size.x * 0.5f - 12.0f - 2 * ImGui::GetStyle().WindowPadding.x);
      ImGui::TextUnformatted(quarters_[std::size_t(q)].label.c_str());
      ImGui::PopTextWrapPos();
      ImGui::End();
    }
  }

 private:
  std::span<Light> lights() override { return p_.lights; }
  tech::LitSettings litSettings() const { return {glm::vec3(p_.ambient), p_.view == View::Visibility ? 1 : 0}; }

  // The same budget for every map technique: one map of texels^2, or the faces / cascades sharing it.
  void equaliseTexels() {
    uniform_.params().mapSize = p_.texels;
    uniform_.params().cubeSize = p_.texels;
    psm_.maps().params().mapSize = p_.texels;
    lispsm_.maps().params().mapSize = p_.texels;
    csm_.maps().params().mapSize = p_.texels;
    sdsm_.maps().params().mapSize = p_.texels;
    hybrid_.params().mapSize = p_.texels;
  }

  // view=maps: light 0's map layers along the bottom row (PSM's faces, LiSPSM's map, the cascades),
  // beside the post-projective inset when it is on; an inset the UI stays clear of.
  void drawMaps(const FrameInfo& f) {
    auto t = scope("map view");
    const int h = f.height / 3, x = postView_.rightOfInset(f.width, f.height);  // beside the post-projective inset
    const std::string name = techniques_.entry(p_.technique).name;
    const int room = std::max(f.width - x, 1);
    if (name == "psm") psm_.drawMaps(0, x, 0, std::min(room, h * 6), h);
    if (name == "lispsm") lispsm_.drawMaps(0, x, 0, h, h);
    tech::CascadedShadowMaps* cascades = name == "csm" ? &csm_ : name == "sdsm" ? &sdsm_ : nullptr;
    if (cascades) cascades->drawMaps(0, x, 0, std::min(room, h * cascades->params().count), h);
    const int w = name == "psm" ? std::min(room, h * 6) : cascades ? std::min(room, h * cascades->params().count) : h;
    if (name == "psm" || name == "lispsm" || cascades)
      insets.push_back({"map view", x, 0, w, h});  // the UI stays clear of it
  }

  // ==== the four-up view: each quarter a technique on the same camera, drawn into its own target ====
  // at a quarter of the frame (the same aspect), then copied into place. Its wall time (glFinish at
  // both ends) is the quarter's figure; the framework's timers see each quarter as one pass
  // ("quarter 0: psm", in --bench too), not the technique's own passes; the ground truth does not
  // judge it (measureSource: one truth, four techniques).
  void renderFourUp(const FrameInfo& f) {
    const int w = std::max(f.width / 2, 1), h = std::max(f.height / 2, 1);
    counters.clear();
    const bool timed = timers.enabled();  // off while the god view re-renders the lesson
    for (int q = 0; q < 4; ++q) {
      Quarter& quarter = quarters_[std::size_t(q)];
      if (quarter.target.width != w || quarter.target.height != h)
        quarter.target = gl::makeRenderTarget(w, h, "10 four-up quarter " + std::to_string(q));
      FrameInfo fq = f;
      fq.width = w;
      fq.height = h;
      fq.framebuffer = quarter.target.fbo.id();
      fq.measureLight = -1;
      glBindFramebuffer(GL_FRAMEBUFFER, fq.framebuffer);
      glViewport(0, 0, w, h);
      tech::ShadowTechnique& t = techniques_[p_.quarter[q]];
      if (timed) timers.begin("quarter " + std::to_string(q) + ": " + t.name());
      timers.setEnabled(false);  // the technique's own passes: the quarter is the figure
      glFinish();
      const auto start = std::chrono::steady_clock::now();
      const tech::ShadowContext c = context(fq);
      t.renderShadows(c);
      drawLit(c, t, litSettings());
      glFinish();
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      timers.setEnabled(timed);
      if (timed) timers.end();
      if (!f.godView) {
        quarter.ms = quarter.ms > 0.0 ? 0.8 * quarter.ms + 0.2 * ms : ms;
        quarter.label = quarterLabel(q, t);
        counters.push_back({"quarter " + std::to_string(q), quarter.label});
      }
      glBindFramebuffer(GL_READ_FRAMEBUFFER, fq.framebuffer);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f.framebuffer);
      const int x0 = (q % 2) * w, y0 = (q < 2 ? h : 0);  // GL rows from the bottom: quarters 0, 1 on top
      glBlitFramebuffer(0, 0, w, h, x0, y0, x0 + w, y0 + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer);
    glViewport(0, 0, f.width, f.height);
  }

  std::string quarterLabel(int q, const tech::ShadowTechnique& t) const {
    const tech::ShadowStats& s = t.stats();
    char b[160];
    std::snprintf(b, sizeof b, "%s  %.0f ms\n%.2f Mtexels  %zuk tris  %.0f MB%s", t.name().c_str(),
                  quarters_[std::size_t(q)].ms, double(s.texels + s.kept.texels) / 1e6,
                  (s.triangles + s.kept.triangles) / 1000, double(s.bytes) / (1024.0 * 1024.0),
                  s.reusedMaps ? "  kept" : "");
    return b;
  }

  Params p_;
  tech::TechniqueSet techniques_{tech::showdownTechniques()};
  // What only some of them have: equal texels, the maps views, the cascades' student hooks.
  tech::UniformShadowMaps& uniform_ = techniques_.get<tech::UniformShadowMaps>("uniform");
  tech::PerspectiveShadowMaps& psm_ = techniques_.get<tech::PerspectiveShadowMaps>("psm");
  tech::LightSpacePsm& lispsm_ = techniques_.get<tech::LightSpacePsm>("lispsm");
  tech::CascadedShadowMaps& csm_ = techniques_.get<tech::CascadedShadowMaps>("csm");
  tech::CascadedShadowMaps& sdsm_ = techniques_.get<tech::CascadedShadowMaps>("sdsm");
  tech::HybridShadowMaps& hybrid_ = techniques_.get<tech::HybridShadowMaps>("hybrid");
  tech::PostProjectiveView postView_;
  std::array<Quarter, 4> quarters_;
};

int main(int argc, char** argv) { return runLesson<ShowdownLesson>(argc, argv); }

#pragma once
// What the lessons about shadow techniques share (03, 05, 07-10): the scene their passes draw, their
// lights in order, the ground truth's view of both, the context their techniques see, and the lit
// pass (the scene from the eye with V from a technique). A lesson derives from it and keeps its
// Params, its techniques and its numbered passes; lesson 04, whose volumes draw the lit frame
// themselves, and lessons 01, 02 and 06, which write their own passes, derive from Lesson.
#include <functional>
#include <span>
#include <string>

#include "app/lesson.hpp"
#include "technique/lit_pass.hpp"
#include "technique/scene_cache.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

class ShadowLesson : public Lesson {
 public:
  // number: the lesson's ("03"): its GL objects are labelled "03 scene". pathMovesLight: a replayed
  // path (--replay) moves light 0 with its key's light position and direction; else only the camera.
  explicit ShadowLesson(const std::string& number, bool pathMovesLight = false)
      : scene_(number + " scene"), lit_(number + " scene"), pathMovesLight_(pathMovesLight) {}
  MeasureSource measureSource() override {
    const std::span<Light> l = lights();
    return {&scene_.scene(), scene_.revision(), {l.begin(), l.end()}};
  }
  void applyPathLight(const glm::vec3& position, const glm::vec3& direction) override;
  // The last drawLit() of the viewer's frame again, from frame's camera (the shimmer figures).
  bool redrawLit(const FrameInfo& frame) override;

 protected:
  // The lesson's lights, in order: light i is uLights[i] in GLSL and light<i>.* in the registry.
  virtual std::span<Light> lights() = 0;
  // What the techniques see of frame f; they fit themselves to the lesson's camera, the viewer.
  ShadowContext context(const FrameInfo& f) { return {f, camera, scene_, lights(), timers, debug}; }
  // This frame's shadow passes with `technique`: when it is the lesson's subject, the lesson's
  // `stages` (its calls of the technique's stages under its numbered banners) and the god view's
  // shapes; any other technique's renderShadows. The god view's frame draws only the shapes again.
  // Then the header's figures (counters) from the technique's stats.
  void shadowPasses(const ShadowContext& c, ShadowTechnique& technique, bool subject,
                    const std::function<void()>& stages);
  // The scene from the eye with V from `technique`: the technique's own lit frame (the stencil
  // volumes), or the frame cleared and the lit pass drawn (timed as "scene").
  void drawLit(const ShadowContext& c, ShadowTechnique& technique, const LitSettings& lit);

  SceneCache scene_;
  LitPass lit_;

 private:
  void clearAndDrawLit(const ShadowContext& c, ShadowTechnique& technique, const LitSettings& lit);
  bool pathMovesLight_;
  ShadowTechnique* litTechnique_ = nullptr;  // the viewer's frame's last drawLit(), for redrawLit()
  LitSettings litSettings_;
};

}  // namespace shadowlab::tech

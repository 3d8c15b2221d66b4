#pragma once
// The lit pass of a map technique: the scene from the frame's camera, every light with its V from
// the technique. The program is shaders/common/scene.vert + scene.frag linked with the technique's
// fragment shader (the one that defines shadowVisibility), one build per technique and set of
// #defines. A lesson whose lit shader is its subject passes its own vertex and fragment files.
#include <string>

#include "gl/program.hpp"
#include "technique/depth_prepass.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

class LitPass {
 public:
  explicit LitPass(std::string label, std::string vertex = "common/scene.vert",
                   std::string fragment = "common/scene.frag")
      : variants_(label, {vertex, std::move(fragment)}), prepass_(label + ": depth pre-pass", vertex) {}
  // The program that serves `technique` and these lights as they are now set (built on first use,
  // specialised for the lights that are on, their kinds, the view and the technique's defines).
  gl::Program& program(const ShadowContext& c, const ShadowTechnique& technique, const LitSettings& settings);
  // The lit pass's own defines (LIGHT_COUNT, LIGHT_ON, LIGHT_KINDS, VIEW) for these lights.
  static std::vector<std::string> lightDefines(std::span<const Light> lights, int view);
  // Draws the scene into the bound framebuffer (material texture on unit 0, the technique's from
  // unit 1 up). Returns the triangles drawn.
  std::size_t draw(const ShadowContext& c, const ShadowTechnique& technique, const LitSettings& settings);

 private:
  gl::ProgramVariants variants_;
  DepthPrepass prepass_;
  bool prepassBuilt_ = false;
};

}  // namespace shadowlab::tech

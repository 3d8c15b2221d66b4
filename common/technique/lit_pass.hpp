#pragma once
// The lit pass of a map technique: the scene from the frame's camera, every light with its V from
// the technique. The program is shaders/common/scene.vert + scene.frag linked with the technique's
// fragment shader (the one that defines shadowVisibility), one build per technique and set of
// #defines. A lesson whose lit shader is its subject passes its own vertex and fragment files.
#include <string>

#include "gl/program.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

class LitPass {
 public:
  explicit LitPass(std::string label, std::string vertex = "common/scene.vert",
                   std::string fragment = "common/scene.frag")
      : variants_(std::move(label), {std::move(vertex), std::move(fragment)}) {}
  // The program that serves `technique` as it is now set (built on first use).
  gl::Program& program(const ShadowTechnique& technique);
  // Draws the scene into the bound framebuffer (material texture on unit 0, the technique's from
  // unit 1 up). Returns the triangles drawn.
  std::size_t draw(const ShadowContext& c, const ShadowTechnique& technique, const LitSettings& settings);

 private:
  gl::ProgramVariants variants_;
};

}  // namespace shadowlab::tech

#pragma once
// The depth pass every shadow-map technique runs once per light camera: the casters that camera
// keeps, drawn with the course's one depth program (shaders/common/depth.vert and .frag), so an
// alpha-tested card discards its holes here too and casts the shadow of its leaves, not of a
// solid card (Boreskov's tutorial, docs/references.md). The caller binds the map's framebuffer
// (gl::beginShadowPass) and sets the polygon offset; the GL calls of the pass are here.
#include <span>

#include <glm/glm.hpp>

#include "gl/program.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

struct CasterOptions {
  bool alphaTest = true;   // discard alpha-tested texels (off: solid cards, the lesson-02 mistake)
  bool cullFront = false;  // draw back faces only: a closed caster's own thickness is the bias
};

class CasterPass {
 public:
  explicit CasterPass(std::string label = "depth pass")
      : program_(std::move(label), {"common/depth.vert", "common/depth.frag"}) {}
  void build() { program_.build(); }
  // Draws object i when keep[i] (an empty span: every object that casts). Returns the triangles drawn.
  std::size_t draw(const SceneCache& scene, const glm::mat4& lightViewProj, std::span<const char> keep,
                   const CasterOptions& options);

 private:
  gl::Program program_;
};

}  // namespace shadowlab::tech

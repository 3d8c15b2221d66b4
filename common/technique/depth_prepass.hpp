#pragma once
// A depth pre-pass: the nearest surfaces' depth first, with a trivial fragment shader (alpha-tested
// holes discarded), then the expensive lit shader runs once per pixel: depth EQUAL, and a stencil
// that lets only the first fragment of a pixel through, so where two surfaces tie in depth the one
// drawn first wins, exactly as a single pass with depth LESS draws it. On a software renderer this
// turns the cost of the lit shader from per overlapping fragment (alpha-tested cards defeat early
// depth tests) into per pixel. The lit pass must use the same vertex shader, with `invariant
// gl_Position`, so the depths match bit for bit.
#include <string>

#include <glm/glm.hpp>

#include "technique/casters.hpp"

namespace shadowlab::tech {

class DepthPrepass {
 public:
  DepthPrepass(std::string label, std::string vertexShader)
      : pass_(std::move(label), std::move(vertexShader), "uViewProj") {}
  void build() { pass_.build(); }
  // Lays down the depth (and stencil 0) of every object, then sets the state for the shading pass.
  void begin(const SceneCache& scene, const glm::mat4& viewProj);
  // Back to plain depth LESS with writes on, stencil off.
  void end();

 private:
  CasterPass pass_;
};

}  // namespace shadowlab::tech

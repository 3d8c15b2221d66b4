#pragma once
// A depth pre-pass: the nearest surfaces' depth first, with a trivial fragment shader (alpha-tested
// holes discarded), then the expensive lit shader runs once per pixel: depth EQUAL, and a stencil
// that lets only the first fragment of a pixel through, so where two surfaces tie in depth the one
// drawn first wins, exactly as a single pass with depth LESS draws it. On a software renderer this
// turns the cost of the lit shader from per overlapping fragment (alpha-tested cards defeat early
// depth tests) into per pixel. The lit pass must use the same vertex shader, with `invariant
// gl_Position`, so the depths match bit for bit.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "technique/casters.hpp"

namespace shadowlab::tech {

// Whether a lesson lays the depth down first: on, off, or auto: on, except while the frame budget
// renders at half the window's size or less. There a scene of many cheap triangles (lesson 02's
// forest, 100,000) pays more for the second geometry pass than for the overdraw it saves (lesson
// 02's README, "Measured"); lit passes whose shading dominates (lessons 03, 05, 07, 10) keep theirs.
enum class PrepassMode { Auto, On, Off };
inline bool prepassOn(PrepassMode mode, float renderScale) {
  return mode == PrepassMode::On || (mode == PrepassMode::Auto && renderScale > 0.5f);
}

class DepthPrepass {
 public:
  DepthPrepass(std::string label, std::string vertexShader)
      : pass_(std::move(label), std::move(vertexShader), "uViewProj") {}
  void build() { pass_.build(); }
  // Lays down the depth (and stencil 0) of every object, then sets the state for the shading pass.
  // With draw false it only culls (inView, culled) and leaves plain depth LESS with writes on: the
  // shading pass then discards its own holes (compiled without DEPTH_PREPASS). Objects go near to
  // far, and a mesh with view orders draws its triangles nearest the eye first (CasterPass).
  void begin(const SceneCache& scene, const glm::mat4& viewProj, bool draw = true);
  // Back to plain depth LESS with writes on, stencil off.
  void end();
  // Whether object i can draw a fragment in the last begin()'s view (its world box not wholly
  // outside one clip plane): the shading pass skips the same objects (a filter for gl::drawScene).
  bool inView(std::size_t i) const { return i < inView_.size() && inView_[i]; }
  std::size_t culled() const { return culled_; }  // objects left out by the view
  // Objects in view whose mesh has view orders: drawn nearest triangle first (here, and by a shading
  // pass that passes the eye as gl::SceneDrawOptions::viewer).
  std::size_t sorted() const { return sorted_; }

 private:
  CasterPass pass_;
  std::vector<char> inView_;
  std::vector<std::uint32_t> order_;  // near to far
  std::vector<float> distance_;
  std::size_t culled_ = 0, sorted_ = 0;
};

}  // namespace shadowlab::tech

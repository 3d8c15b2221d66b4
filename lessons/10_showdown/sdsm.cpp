#include "sdsm.hpp"

#include <cstdio>
#include <cstring>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/shadow_math.hpp"
#include "gl/texture.hpp"
#include "gl/timer.hpp"

namespace shadowlab::tech {

void DepthTileReduction::init() {
  depth_.build();
  for (gl::Program* p : {&tiles_, &reduce_}) {
    p->keepUnderFloor();  // the tiles size the cascades: data, not shading
    p->build();
  }
  vao_ = gl::makeVertexArray("sdsm: passes");
  depthFbo_ = gl::makeFramebuffer("sdsm: camera depth");
  passFbo_ = gl::makeFramebuffer("sdsm: reduction");
}

// The depth texture at the frame's size and the reduction's levels under it: tiles of 8 pixels,
// then half the side each step until at most kMaxTiles a side.
void DepthTileReduction::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  depthTexture_ =
      gl::makeTexelGrid(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, width, height, "sdsm: camera depth");
  glBindFramebuffer(GL_FRAMEBUFFER, depthFbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture_.id(), 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
  gl::requireComplete(GL_FRAMEBUFFER, "sdsm: camera depth");
  levels_.clear();
  int w = (width + kTile - 1) / kTile, h = (height + kTile - 1) / kTile, pixels = kTile;
  for (;;) {
    const std::string label = "sdsm: tiles of " + std::to_string(pixels) + " pixels";
    levels_.push_back({gl::makeTexelGrid(GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, w, h, label), w, h, pixels});
    if (w <= kMaxTiles && h <= kMaxTiles) break;
    w = (w + 1) / 2, h = (h + 1) / 2, pixels *= 2;
  }
}

shadow::DepthTiles DepthTileReduction::run(const ShadowContext& c, const shadow::CascadeViewer& viewer, bool reuse) {
  resize(c.frame.width, c.frame.height);
  const glm::mat4 viewProj = glm::perspective(viewer.fovY, viewer.aspect, viewer.nearZ, viewer.farZ) * viewer.view;
  PassKey key;
  key << c.scene.revision() << viewProj << width_ << height_;
  if (reuse && key == reduced_) return last_;
  // ---- 0. the camera's depth: every object, alpha-tested holes discarded, as the lit pass sees it
  {
    auto t = gl::TimerScope(c.timers, "sdsm depth");
    glBindFramebuffer(GL_FRAMEBUFFER, depthFbo_.id());
    glViewport(0, 0, width_, height_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    keep_.assign(c.scene.boxes().size(), 1);  // what cannot reach the frame is not drawn
    for (std::size_t i = 0; i < keep_.size(); ++i) keep_[i] = !shadow::boxOutsideClip(viewProj, c.scene.boxes()[i]);
    depth_.draw(c.scene, viewProj, keep_, {.alphaTest = true, .allObjects = true, .alphaLevel0 = false});
  }
  // ---- 1. the reduction: nearest and farthest depth per tile, then per 2 x 2 tiles, ...
  {
    auto t = gl::TimerScope(c.timers, "sdsm reduction");
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glBindFramebuffer(GL_FRAMEBUFFER, passFbo_.id());
    const GLenum colour = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &colour);
    glBindVertexArray(vao_.id());
    for (std::size_t k = 0; k < levels_.size(); ++k) {
      const Level& l = levels_[k];
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, l.texture.id(), 0);
      glViewport(0, 0, l.width, l.height);
      const gl::Program& p = k == 0 ? tiles_ : reduce_;
      p.use();
      if (k == 0) {
        gl::bindTexelUnit(0, depthTexture_.id());
        p.set("uDepth", 0);
        p.set("uSize", glm::ivec2(width_, height_));
        p.set("uTile", kTile);
        p.set("uNear", viewer.nearZ);
        p.set("uFar", viewer.farZ);
      } else {
        gl::bindTexelUnit(0, levels_[k - 1].texture.id());
        p.set("uTiles", 0);
        p.set("uSize", glm::ivec2(levels_[k - 1].width, levels_[k - 1].height));
      }
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl::bindTexelUnit(0, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
  }
  // ---- the tiles read back: OpenGL ES reads an integer target only as RGBA_INTEGER
  const Level& top = levels_.back();
  std::vector<std::uint32_t> words(std::size_t(top.width) * std::size_t(top.height) * 4);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, top.width, top.height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, words.data());
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);

  shadow::DepthTiles tiles;
  tiles.width = top.width;
  tiles.height = top.height;
  tiles.tilePixels = top.pixels;
  tiles.pixelsWide = width_;
  tiles.pixelsHigh = height_;
  tiles.viewer = viewer;
  tiles.depths.resize(std::size_t(top.width) * std::size_t(top.height));
  for (std::size_t i = 0; i < tiles.depths.size(); ++i)
    std::memcpy(&tiles.depths[i], &words[4 * i], sizeof(glm::vec2));  // the float bits, back to floats
  reduced_ = std::move(key);
  last_ = tiles;
  return tiles;
}

// ---- the technique: the cascades' parameters under sdsm., and its own two -----------------------

void SampleDistributionShadowMaps::declare(ParamRegistry& r, const std::string& n) {
  CascadedShadowMaps::declare(r, n);
  r.add(n + "latency", &s_.latency, 0, 2,
        "fit to the depth tiles of this many frames ago (an engine reads them back late so the GPU never waits)");
  r.add(n + "tight_fit", &s_.tightFit,
        "each cascade's map fitted to the points its tiles saw (off: to its whole slice of the view)");
}

void SampleDistributionShadowMaps::init() {
  CascadedShadowMaps::init();
  reduction_.init();
}

// ==== 0.-1. the camera's depth, reduced to tiles (once a frame, for every light) ===============
void SampleDistributionShadowMaps::render(const ShadowContext& c) {
  const shadow::CascadeViewer viewer{c.viewer.view(), c.viewer.fovY, c.viewerAspect(), c.viewer.nearZ, c.viewer.farZ};
  bool directional = false;
  for (const Light& l : c.lights) directional = directional || (l.enabled && l.kind == LightKind::Directional);
  if (directional) {
    // A second view of the same frame (the A/B split's B half, a four-up quarter) replaces this
    // frame's tiles instead of ageing the others by a frame.
    if (!history_.empty() && history_.front().frame == c.frame.index)
      history_.front().tiles = reduction_.run(c, viewer, maps().params().reuseMaps);
    else history_.push_front({c.frame.index, reduction_.run(c, viewer, maps().params().reuseMaps)});
    while (int(history_.size()) > s_.latency + 1) history_.pop_back();
  }
  CascadedShadowMaps::render(c);
}

// ==== 2. the splits over the depths on screen, each cascade fitted to its tiles ===============
shadow::CascadeSet SampleDistributionShadowMaps::fitSet(const ShadowContext& c, const glm::vec3& direction,
                                                        const shadow::CascadeViewer& viewer,
                                                        const shadow::CascadeOptions& o, const std::string& n) {
  shadow::SdsmOptions so;
  so.cascades = o;
  so.band = params().band;
  so.tightFit = s_.tightFit;
  // The oldest tiles kept: `latency` frames old once the history is full (the first frames use
  // the oldest there is).
  const shadow::SdsmFit fit =
      shadow::fitSampleDistribution(direction, c.scene.casterBoxes(), viewer, history_.back().tiles, so);
  char b[160];
  const int age = int(history_.size()) - 1;
  const std::string old = age == 0 ? "" : ", " + std::to_string(age) + (age == 1 ? " frame old" : " frames old");
  if (fit.fellBack) std::snprintf(b, sizeof b, "nothing on screen: the practical splits");
  else
    std::snprintf(b, sizeof b, "%.3g - %.3g m, %d of %d tiles%s", fit.range.nearest, fit.range.farthest,
                  fit.range.tiles, int(history_.back().tiles.depths.size()), old.c_str());
  stats_.extra.push_back({n + "depth range", b});
  return fit.set;
}

}  // namespace shadowlab::tech

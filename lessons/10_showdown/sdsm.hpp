#pragma once
// Sample distribution shadow maps (Lauritzen, Salvi and Lefohn, I3D 2011): the cascades of
// cascades.hpp, split over the depths the camera actually sees and each fitted to the points it
// sees, found on the GPU each frame:
//   0. the camera's depth       the scene from the viewer into a depth texture of the frame's size
//   1. the reduction            tiles of 8 x 8 pixels, then 2 x 2 of those, ... each texel the
//                               nearest and farthest view depth under it (shaders/10_showdown/
//                               sdsm_tiles.frag, sdsm_reduce.frag: fragment passes, OpenGL 4.1 has no
//                               compute), until at most 128 x 128 tiles remain (a 1280 x 720 frame:
//                               80 x 45 tiles of 16 pixels); those are read back
//   2. the fit                  GL-free (algorithms/sdsm): the practical split scheme over the tiles'
//                               [nearest, farthest], each cascade's map fitted to the tiles' pieces of
//                               its slice (tight_fit), then the cascades' passes and lookup unchanged.
// An engine reads the tiles back a frame or two late so the GPU never waits; `latency` fits this
// frame's cascades to tiles 0, 1 or 2 frames old (read back at once here: a few kilobytes) to show
// what that costs when the camera moves. Directional lights only, as the cascades.
#include <deque>

#include "algorithms/sdsm.hpp"
#include "cascades.hpp"
#include "gl/objects.hpp"
#include "technique/casters.hpp"
#include "technique/pass_key.hpp"

namespace shadowlab::tech {

class DepthTileReduction {
 public:
  static constexpr int kTile = 8;        // the first step's tile, in pixels
  static constexpr int kMaxTiles = 128;  // reduce until at most this many tiles a side
  void init();
  // The scene's depth from `viewer` at the frame's size, reduced and read back (passes timed).
  // reuse: the last tiles, untouched, while the viewer, the frame's size and the scene are (a still
  // camera's maps are kept: their depth distribution cannot have moved).
  shadow::DepthTiles run(const ShadowContext& c, const shadow::CascadeViewer& viewer, bool reuse);

 private:
  void resize(int width, int height);
  CasterPass depth_{"sdsm: camera depth"};
  gl::Program tiles_{"sdsm: depth tiles", {"common/fullscreen.vert", "10_showdown/sdsm_tiles.frag"}};
  gl::Program reduce_{"sdsm: depth reduction", {"common/fullscreen.vert", "10_showdown/sdsm_reduce.frag"}};
  gl::Texture depthTexture_;
  gl::Framebuffer depthFbo_, passFbo_;
  gl::VertexArray vao_;
  struct Level {
    gl::Texture texture;                    // RGBA32UI (nearest, farthest) as float bits
    int width = 0, height = 0, pixels = 0;  // pixels: a texel's side in the frame's pixels
  };
  std::vector<Level> levels_;
  std::vector<char> keep_;
  int width_ = 0, height_ = 0;
  PassKey reduced_;  // what the last tiles were reduced from
  shadow::DepthTiles last_;
};

struct SdsmParams {
  int latency = 0;       // fit to the tiles of this many frames ago (an engine's asynchronous read-back)
  bool tightFit = true;  // each cascade fitted to its tiles' points; off: to its whole slice of the view
};

class SampleDistributionShadowMaps : public CascadedShadowMaps {
 public:
  std::string name() const override { return "sdsm"; }
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;

 protected:
  void render(const ShadowContext& c) override;
  shadow::CascadeSet fitSet(const ShadowContext& c, const glm::vec3& direction, const shadow::CascadeViewer& viewer,
                            const shadow::CascadeOptions& o, const std::string& n) override;

 private:
  SdsmParams s_;
  DepthTileReduction reduction_;
  struct FrameTiles {
    int frame = 0;  // FrameInfo::index
    shadow::DepthTiles tiles;
  };
  std::deque<FrameTiles> history_;  // newest first: [latency] is the one fitted to
};

}  // namespace shadowlab::tech

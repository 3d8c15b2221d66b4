#pragma once
// A depth map as an image, in a rectangle of the frame: the inner buffer a lecturer shows when
// asking "what does the light see?". Perspective maps are linearised (near casters dark, the empty
// far plane white); orthographic ones are linear already.
#include <optional>

#include <glm/glm.hpp>

#include "gl/program.hpp"
#include "gl/shadow_map.hpp"

namespace shadowlab::tech {

class DepthMapView {
 public:
  void build();
  // Draws `map` (a 2D map) into the viewport (x, y, width, height) of the bound framebuffer, reading
  // it through texture unit `unit`. nearFar: the perspective light frustum's depth range, or none.
  void draw(const gl::ShadowMap& map, int x, int y, int width, int height, std::optional<glm::vec2> nearFar,
            int unit = 7);

 private:
  gl::Program program_{"depth map view", {"common/fullscreen.vert", "common/depth_view.frag"}};
  gl::Sampler raw_;
  gl::VertexArray vao_;
};

}  // namespace shadowlab::tech

#pragma once
// Texture filtering checked on the CPU (lesson 06). A scene pass that writes a gl::FootprintTarget
// (colour, uv + coverage, d(uv)/dx and d(uv)/dy per pixel) can be re-sampled pixel by pixel by a
// CPU sampler (algorithms/texture_sampling, or a student's exercises): the picture it gives, or
// |GPU - CPU| amplified, and their RMSE; and compared with the same frame rendered at
// supersample^2 the pixels and box-filtered down (error and frame-to-frame flicker of both).
#include <cstddef>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/objects.hpp"
#include "gl/texture.hpp"
#include "gl/texture_modes.hpp"

namespace shadowlab {

class FootprintReference {
 public:
  // The CPU sampler: the filtered colour at uv for the pixel's derivatives.
  using Sampler = std::function<glm::vec4(glm::vec2 uv, glm::vec2 dx, glm::vec2 dy)>;
  struct Result {
    double rmse = 0;         // of 255, over the covered pixels' RGB
    std::size_t pixels = 0;  // covered pixels sampled
  };

  // A view of `width` x `height` (call on every resize).
  void resize(int width, int height);
  // Samples every covered pixel of `scene` with `sample`; the view shows the CPU's picture, or
  // with `difference` |GPU - CPU| times `gain`. Pixels the scene did not texture keep the GPU's,
  // and so do all of them with an empty sampler (what the CPU cannot sample: a 3D texture).
  // Rows are sampled on `threads` threads (0: every core; the sampler must then be safe to call
  // from several at once); the figures do not depend on the count.
  Result sample(const gl::FootprintTarget& scene, const Sampler& sample, bool difference, float gain, int threads = 0);
  // The framebuffer holding the last sample()'s view (to blit to the screen).
  GLuint framebuffer() const { return fbo_.id(); }

 private:
  int width_ = 0, height_ = 0;
  gl::Texture view_;
  gl::Framebuffer fbo_;
};

// The frame against itself at supersample^2 the pixels: `draw` renders the scene with the best
// filter into the target it is given; errors of the current frame (`scene`, width x height) and
// the frame-to-frame change of both, kept from the previous call.
class SupersampledError {
 public:
  struct Result {
    double rmse = 0, flicker = 0, referenceFlicker = 0;
    int referenceWidth = 0, referenceHeight = 0;
  };
  Result measure(const gl::FootprintTarget& scene, int supersample,
                 const std::function<void(const gl::FootprintTarget&)>& draw);
  void reset();  // forget the previous frame (a resize)

 private:
  gl::FootprintTarget target_;
  std::vector<float> previous_, previousReference_;
};

}  // namespace shadowlab

#include "app/footprint_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "algorithms/texture_sampling.hpp"
#include "core/parallel.hpp"
#include "gl/objects.hpp"

namespace shadowlab {

void FootprintReference::resize(int width, int height) {
  width_ = width;
  height_ = height;
  view_ = gl::uploadLevel(ImageF{width, height, 4, std::vector<float>(std::size_t(width) * height * 4)},
                          "footprint reference view");
  fbo_ = gl::makeFramebuffer("footprint reference fbo");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, view_.id(), 0);
  gl::requireComplete(GL_FRAMEBUFFER, "footprint reference fbo");
}

FootprintReference::Result FootprintReference::sample(const gl::FootprintTarget& scene, const Sampler& sampler,
                                                      bool difference, float gain, int threads) {
  const int w = width_, h = height_;
  const std::vector<glm::vec4> uv = gl::readFloatPixels(scene.fbo.id(), 1, 0, 0, w, h);
  const std::vector<glm::vec4> d = gl::readFloatPixels(scene.fbo.id(), 2, 0, 0, w, h);
  const Image8 gpu = gl::readPixels(scene.fbo.id(), w, h);
  Image8 out = gpu;
  // Per row, summed after: squared differences of whole numbers add up exactly in any order.
  std::vector<double> rowSum(std::size_t(std::max(h, 0)), 0.0);
  std::vector<std::size_t> rowPixels(rowSum.size(), 0);
  if (sampler)
    parallelRows(h, threads, [&](int y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(h - 1 - y) * w + x;  // GL rows are bottom first
        if (uv[i].z < 0.5f) continue;
        const glm::vec4 c = sampler({uv[i].x, uv[i].y}, {d[i].x, d[i].y}, {d[i].z, d[i].w});
        std::uint8_t* o = out.at(x, y);
        const std::uint8_t* g = gpu.at(x, y);
        for (int k = 0; k < 3; ++k) {
          const int v = int(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
          rowSum[std::size_t(y)] += double(v - g[k]) * double(v - g[k]);
          o[k] = std::uint8_t(difference ? std::min(255.0f, std::abs(float(v - g[k])) * gain) : float(v));
        }
        ++rowPixels[std::size_t(y)];
      }
    });
  double sum = 0;
  Result r;
  for (std::size_t y = 0; y < rowSum.size(); ++y) {
    sum += rowSum[y];
    r.pixels += rowPixels[y];
  }
  r.rmse = std::sqrt(sum / std::max<double>(1, 3.0 * double(r.pixels)));
  Image8 flipped = out;  // back to GL's bottom-first rows for the texture
  for (int y = 0; y < h; ++y) std::copy_n(out.at(0, h - 1 - y), std::size_t(w) * 4, flipped.at(0, y));
  gl::updateLevel(view_.id(), flipped);
  return r;
}

SupersampledError::Result SupersampledError::measure(const gl::FootprintTarget& scene, int s,
                                                     const std::function<void(const gl::FootprintTarget&)>& draw) {
  const int w = scene.width, h = scene.height;
  if (target_.width != w * s || target_.height != h * s)
    target_ = gl::makeFootprintTarget(w * s, h * s, false, "supersampled reference");
  draw(target_);
  const std::vector<float> ref = sampling::boxReduceRgb(gl::readPixels(target_.fbo.id(), w * s, h * s), s);
  std::vector<float> cur = sampling::boxReduceRgb(gl::readPixels(scene.fbo.id(), w, h), 1);
  Result r{sampling::rmse(cur, ref), sampling::meanAbsDifference(cur, previous_),
           sampling::meanAbsDifference(ref, previousReference_), w * s, h * s};
  previous_ = std::move(cur);
  previousReference_ = ref;
  return r;
}

void SupersampledError::reset() {
  target_ = {};
  previous_.clear();
  previousReference_.clear();
}

}  // namespace shadowlab

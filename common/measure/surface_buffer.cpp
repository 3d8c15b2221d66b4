// The surface a ground-truth query traces from (ground_truth.hpp): built from the lesson's
// position and normal images, checked, downsampled. GL-free and Embree-free, so the browser build
// (which has no ground truth) shares it.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "measure/ground_truth.hpp"

namespace shadowlab::measure {

SurfaceBuffer::SurfaceBuffer(int w, int h) : width(w), height(h) {
  if (w < 0 || h < 0)
    throw std::invalid_argument("SurfaceBuffer: size " + std::to_string(w) + "x" + std::to_string(h) + " is negative");
  std::size_t n = std::size_t(w) * std::size_t(h);
  position.assign(n, glm::vec3(0));
  normal.assign(n, glm::vec3(0, 1, 0));
  covered.assign(n, 0);
}

void SurfaceBuffer::validate() const {
  std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
  if (width < 0 || height < 0 || position.size() != n || normal.size() != n || covered.size() != n)
    throw std::invalid_argument("SurfaceBuffer: " + std::to_string(width) + "x" + std::to_string(height) + " needs " +
                                std::to_string(n) + " entries, has position " + std::to_string(position.size()) +
                                ", normal " + std::to_string(normal.size()) + ", covered " +
                                std::to_string(covered.size()));
}

SurfaceBuffer surfaceFromImages(const ImageF& position, const ImageF& normal) {
  if (position.width != normal.width || position.height != normal.height)
    throw std::invalid_argument("surfaceFromImages: position is " + std::to_string(position.width) + "x" +
                                std::to_string(position.height) + ", normal is " + std::to_string(normal.width) + "x" +
                                std::to_string(normal.height));
  if (position.channels != 4 || normal.channels < 3)
    throw std::invalid_argument(
        "surfaceFromImages: need 4 position channels (xyz + coverage) and >= 3 normal "
        "channels, got " +
        std::to_string(position.channels) + " and " + std::to_string(normal.channels));
  std::size_t n = std::size_t(position.width) * position.height;
  if (position.data.size() != n * 4 || normal.data.size() != n * std::size_t(normal.channels))
    throw std::invalid_argument("surfaceFromImages: data size does not match width x height x channels");
  SurfaceBuffer s(position.width, position.height);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      if (!(position.at(x, y, 3) > 0.0f)) continue;
      glm::vec3 nrm(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2));
      float len = glm::length(nrm);
      if (!(len > 0.0f)) continue;  // no usable normal: treat as background
      s.set(x, y, {position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2)}, nrm / len);
    }
  return s;
}

SurfaceBuffer downsample(const SurfaceBuffer& surface, int factor) {
  surface.validate();
  if (factor < 1) throw std::invalid_argument("downsample: factor " + std::to_string(factor) + " < 1");
  SurfaceBuffer out((surface.width + factor - 1) / factor, (surface.height + factor - 1) / factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      int sx = std::min(x * factor + factor / 2, surface.width - 1);
      int sy = std::min(y * factor + factor / 2, surface.height - 1);
      std::size_t i = surface.index(sx, sy), o = out.index(x, y);
      out.position[o] = surface.position[i];
      out.normal[o] = surface.normal[i];
      out.covered[o] = surface.covered[i];
    }
  return out;
}

}  // namespace shadowlab::measure

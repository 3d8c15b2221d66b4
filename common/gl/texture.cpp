#include "gl/texture.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/paths.hpp"
#include "gl/caps.hpp"

namespace shadowlab::gl {

Texture uploadTexture(const Image8& image, const std::string& label, bool mipmaps, ColorData color) {
  static constexpr GLenum kFormats[] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
  static constexpr GLenum kSrgb[] = {0, GL_R8, GL_RG8, GL_SRGB8, GL_SRGB8_ALPHA8};
  static constexpr GLenum kLinear[] = {0, GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
  const GLenum* kInternal = color == ColorData::Srgb ? kSrgb : kLinear;
  // Past the limit glTexImage2D fails with GL_INVALID_VALUE and the texture samples black.
  if (const std::string problem = textureSizeProblem(image.width, image.height); !problem.empty())
    throw std::runtime_error("texture '" + label + "': " + problem);
  if (image.channels < 1 || image.channels > 4)
    throw std::runtime_error("texture '" + label + "': " + std::to_string(image.channels) + " channels (1 to 4)");
  Texture tex = makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // The course's uv convention: v = 0 is the image's FIRST (top) row, so files go up unflipped.
  // Procedural meshes are built for it, core/model_file flips model files' v, and the ground truth's alpha
  // test (common/measure) samples the same way: rasteriser and rays see the same holes.
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(kInternal[image.channels]), image.width, image.height, 0,
               kFormats[image.channels], GL_UNSIGNED_BYTE, image.data.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  if (mipmaps) {
    glGenerateMipmap(GL_TEXTURE_2D);
    // Trilinear only: anisotropic filtering is lesson 06's subject (its own switch), and on a
    // software rasteriser it multiplies the cost of every textured pixel (measured: a 1280x720
    // frame of lesson 01 went from ~300 to ~750 ms with 8x on llvmpipe).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  } else {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  return tex;
}

Texture loadTexture(const std::string& name) {
  return uploadTexture(loadImage(texturePath(name), 4), "texture:" + name);
}

Image8 readPixels(GLuint fbo, int width, int height) {
  Image8 img;
  img.width = width;
  img.height = height;
  img.channels = 4;
  img.data.resize(std::size_t(width) * height * 4);
  std::vector<std::uint8_t> raw(img.data.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  const std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::memcpy(&img.data[std::size_t(y) * row], &raw[std::size_t(height - 1 - y) * row], row);
  return img;
}

Texture makeTexelGrid(GLenum internal, GLenum format, GLenum type, int width, int height, const std::string& label,
                      const void* data) {
  Texture t = makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), width, height, 0, format, type, data);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

void bindTexelUnit(int unit, GLuint texture) {
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindSampler(GLuint(unit), 0);
}

}  // namespace shadowlab::gl

#pragma once
// Textures from files under textures/ (PNG through core/image) or from CPU images, and
// framebuffer read-backs into CPU images.
#include <string>

#include "core/image.hpp"
#include "gl/objects.hpp"

namespace shadowlab::gl {

// uv convention: v = 0 is the image file's top row (uploaded unflipped; see texture.cpp).
// Loads textures/<name> with a full mip chain, trilinear filtering and repeat wrapping (no
// anisotropy: see lesson 06). Throws std::runtime_error naming the path when it cannot be read.
Texture loadTexture(const std::string& name);
// Colour images (3 or 4 channels) are sRGB-encoded pictures: sampling decodes them to linear.
// `ColorData::Linear` for images whose bytes are the values to show as they are (the ground truth's
// heatmaps and visibility, drawn straight into the frame): decoding those too darkened visibility
// 0.53 (136) to 63.
enum class ColorData { Srgb, Linear };
Texture uploadTexture(const Image8& image, const std::string& label, bool mipmaps = true,
                      ColorData color = ColorData::Srgb);

// A 2D texture read texel by texel (texelFetch): nearest filtering, one level, `data` uploaded
// rows of 4-byte alignment (nullptr: storage only). Lesson 07's hybrid grids, lesson 10's depth tiles.
Texture makeTexelGrid(GLenum internal, GLenum format, GLenum type, int width, int height, const std::string& label,
                      const void* data = nullptr);
// Binds the 2D `texture` on `unit` with no sampler object: texelFetch reads the texture's own state.
void bindTexelUnit(int unit, GLuint texture);

// Reads the colour attachment 0 of `fbo` (0: the default framebuffer) into a top-row-first image.
Image8 readPixels(GLuint fbo, int width, int height);

}  // namespace shadowlab::gl

#pragma once
// GL side of lesson 06's texture filtering: uploads that keep the CPU and the GPU on the very same
// texels (every mip level given explicitly, linear RGBA8, row 0 at t = 0, no sRGB decode; a
// texture's chain and RIP atlas together), the sampler state of algorithms/texture_sampling applied
// to a GL sampler object, and the scene target with read-backs of the float buffers a pass wrote
// (uv and derivatives per pixel) for the CPU reference sampler.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/texture_sampling.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"

namespace shadowlab::gl {

// GL enums of the sampler modes.
GLenum wrapEnum(sampling::Wrap wrap);
GLenum magFilterEnum(sampling::Filter mag);
GLenum minFilterEnum(sampling::Filter min, sampling::MipFilter mip);  // e.g. GL_LINEAR_MIPMAP_NEAREST

// A 2D texture holding `chain` level by level (GL_RGBA8, row 0 first), GL_TEXTURE_MAX_LEVEL set to
// its last level. Throws std::invalid_argument for an empty chain.
Texture uploadMipChain(const std::vector<ImageF>& chain, const std::string& label);
// One level, nearest, clamp: atlases read with texelFetch, CPU images shown on screen.
Texture uploadLevel(const ImageF& image, const std::string& label);
void updateLevel(GLuint texture, const Image8& image);  // same size, replaces the texels
// A 3D texture (GL_RGBA8, n^3) from `voxels` (n^3 RGBA bytes), trilinear-ready with mipmaps off.
Texture uploadVolume(int n, const std::vector<std::uint8_t>& voxels, const std::string& label);

// A texture on both sides of the comparison: its mip chain on the CPU (what the reference sampler
// reads), the same chain on the GPU, and its RIP map as one atlas with the level offsets the shader's
// texelFetch needs.
struct FilterTexture {
  std::vector<ImageF> chain;
  Texture mips, rip;
  std::vector<int> ripOffsetX, ripOffsetY;
  glm::ivec2 size() const { return {chain[0].width, chain[0].height}; }
};
// Builds and uploads the chain and the RIP atlas of `base` (labels: `label`, "`label` RIP atlas").
FilterTexture uploadFilterTexture(const ImageF& base, const std::string& label);
// The uniforms a shader reading `t`'s RIP atlas takes: uTexSize (level 0's size), uRipLevels[2]
// (levels along x and y), uRipOffsetX[] and uRipOffsetY[] (each level's offset in the atlas).
void setRipUniforms(const Program& program, const FilterTexture& t);

// The sampler state on a GL sampler object. The anisotropy is clamped to what the context offers
// (1 without the extension); returns the anisotropy actually set.
float applySamplerState(GLuint sampler, const sampling::SamplerState& s);

// The scene's target: colour (RGBA8), the uv + coverage + lambda (RGBA32F) and the derivatives
// (RGBA32F) of every pixel, and depth. `aux` false: colour and depth only (supersampled renders).
struct FootprintTarget {
  Framebuffer fbo;
  Texture color, uv, derivatives;
  Renderbuffer depth;
  int width = 0, height = 0;
};
FootprintTarget makeFootprintTarget(int width, int height, bool aux, const std::string& label);
// Binds `t` with its viewport and clears it for a scene pass: colour to `background`, uv + coverage
// and derivatives (when it has them) to 0, the "no texture here" of the readouts, and depth.
void clearFootprintTarget(const FootprintTarget& t, const glm::vec3& background);

// RGBA32F attachment `attachment` of `fbo`, `width` x `height` from (x, y) (GL's bottom-left
// origin), rows bottom first as GL returns them.
std::vector<glm::vec4> readFloatPixels(GLuint fbo, int attachment, int x, int y, int width, int height);

}  // namespace shadowlab::gl

#pragma once
// Depth textures for shadow maps (lessons 02 and 03): a 2D map or a cube map with its own
// framebuffer, in one of the depth formats of ARB_depth_texture ([Boreskov2005]), and the two ways to
// read it: a comparison sampler (ARB_shadow: compare mode R-to-texture, LEQUAL; 1 lit, 0 shadowed;
// GL_LINEAR gives hardware 2x2 PCF) and a raw sampler (the stored depth, for a comparison written
// in the shader and for viewing the map). Both are sampler objects, so the same texture can sit on
// two units, one per sampler type, and the shader can switch between them.
#include <string>

#include "gl/objects.hpp"

namespace shadowlab::gl {

enum class DepthFormat { Depth16, Depth24, Depth32F };
GLenum depthInternalFormat(DepthFormat format);  // GL_DEPTH_COMPONENT16 / 24 / 32F
const char* depthFormatName(DepthFormat format);

struct ShadowMap {
  Texture texture;  // GL_TEXTURE_2D or GL_TEXTURE_CUBE_MAP
  Framebuffer fbo;  // depth attachment only; no colour buffer
  int size = 0;
  DepthFormat format = DepthFormat::Depth24;
  bool cube = false;
  GLenum target() const { return cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D; }
};

// size x size (each face of a cube). Throws std::invalid_argument for a size outside 1..16384,
// std::runtime_error when the framebuffer is incomplete (naming `label`).
ShadowMap makeShadowMap(int size, DepthFormat format, const std::string& label);
ShadowMap makeShadowCube(int size, DepthFormat format, const std::string& label);

// Binds the map's framebuffer for a depth-only pass (cube: with face 0..5 attached), sets the
// viewport to the map and clears the depth to 1. The caller rebinds its own framebuffer after.
void beginShadowPass(const ShadowMap& map, int face = -1);

// A comparison sampler (sampler2DShadow / samplerCubeShadow): LEQUAL, GL_NEAREST or GL_LINEAR
// (hardware 2x2 PCF). A raw sampler (sampler2D): GL_NEAREST, no comparison. 2D ones clamp to a
// border of depth 1, so everything outside the map counts as lit.
Sampler makeCompareSampler(bool linear, const std::string& label);
Sampler makeRawDepthSampler(const std::string& label);

}  // namespace shadowlab::gl

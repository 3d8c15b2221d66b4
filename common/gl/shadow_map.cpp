#include "gl/shadow_map.hpp"

#include "gl/caps.hpp"

#include <stdexcept>

namespace shadowlab::gl {

GLenum depthInternalFormat(DepthFormat format) {
  switch (format) {
    case DepthFormat::Depth16: return GL_DEPTH_COMPONENT16;
    case DepthFormat::Depth24: return GL_DEPTH_COMPONENT24;
    case DepthFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
  }
  return GL_DEPTH_COMPONENT24;
}

const char* depthFormatName(DepthFormat format) {
  switch (format) {
    case DepthFormat::Depth16: return "DEPTH_COMPONENT16";
    case DepthFormat::Depth24: return "DEPTH_COMPONENT24";
    case DepthFormat::Depth32F: return "DEPTH_COMPONENT32F";
  }
  return "?";
}

namespace {
void checkSize(int size, const std::string& label) {
  if (size < 1 || size > 16384)
    throw std::invalid_argument("shadow map '" + label + "': size " + std::to_string(size) + " is not in 1..16384");
}

void allocate(GLenum target, int size, DepthFormat format) {
  const GLenum type = format == DepthFormat::Depth32F ? GL_FLOAT : GL_UNSIGNED_INT;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  if (target == GL_TEXTURE_CUBE_MAP) {
    for (int f = 0; f < 6; ++f)
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GLint(depthInternalFormat(format)), size, size, 0,
                   GL_DEPTH_COMPONENT, type, nullptr);
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(depthInternalFormat(format)), size, size, 0, GL_DEPTH_COMPONENT, type,
                 nullptr);
  }
}

ShadowMap make(int size, DepthFormat format, bool cube, const std::string& label) {
  checkSize(size, label);
  ShadowMap m;
  m.size = size;
  m.format = format;
  m.cube = cube;
  m.texture = makeTexture(m.target(), label + " depth");
  glBindTexture(m.target(), m.texture.id());
  allocate(m.target(), size, format);
  glBindTexture(m.target(), 0);
  m.fbo = makeFramebuffer(label + " fbo");
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, m.fbo.id());
  if (cube)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X, m.texture.id(), 0);
  else glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m.texture.id(), 0);
  glDrawBuffer(GL_NONE);  // depth only: the light pass writes no colour ([Boreskov2005], pass 1)
  glReadBuffer(GL_NONE);
  try {
    requireComplete(GL_FRAMEBUFFER, label);
  } catch (...) {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    throw;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return m;
}
}  // namespace

ShadowMap makeShadowMap(int size, DepthFormat format, const std::string& label) {
  return make(size, format, false, label);
}
ShadowMap makeShadowCube(int size, DepthFormat format, const std::string& label) {
  return make(size, format, true, label);
}

void beginShadowPass(const ShadowMap& map, int face) {
  glBindFramebuffer(GL_FRAMEBUFFER, map.fbo.id());
  if (map.cube) {
    if (face < 0 || face > 5)
      throw std::invalid_argument("beginShadowPass: cube face " + std::to_string(face) + " is not in 0..5");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                           map.texture.id(), 0);
  }
  glViewport(0, 0, map.size, map.size);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
}

namespace {
// Outside the map is lit: a border of depth 1. Without GL_CLAMP_TO_BORDER (WebGL2) the edge is
// clamped and the shaders test the range instead (SHADOWLAB_NO_BORDER_CLAMP, gl/program.cpp).
void clampToBorder(GLuint s) {
  if (!caps().clampToBorder) {
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glSamplerParameteri(s, wrap, GL_CLAMP_TO_EDGE);
    return;
  }
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
}
}  // namespace

Sampler makeCompareSampler(bool linear, const std::string& label) {
  Sampler s = makeSampler(label);
  const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
  glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  clampToBorder(s.id());
  return s;
}

Sampler makeRawDepthSampler(const std::string& label) {
  Sampler s = makeSampler(label);
  glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
  clampToBorder(s.id());
  return s;
}

}  // namespace shadowlab::gl

#include "gl/objects.hpp"

#include <cstdio>
#include <stdexcept>

#include "gl/debug.hpp"

namespace shadowlab::gl {

Buffer makeBuffer(GLenum target, const std::string& name) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  glBindBuffer(target, id);
  label(GL_BUFFER, id, name);
  glBindBuffer(target, 0);
  return Buffer(id);
}

VertexArray makeVertexArray(const std::string& name) {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  glBindVertexArray(id);
  label(GL_VERTEX_ARRAY, id, name);
  glBindVertexArray(0);
  return VertexArray(id);
}

Texture makeTexture(GLenum target, const std::string& name) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(target, id);
  label(GL_TEXTURE, id, name);
  glBindTexture(target, 0);
  return Texture(id);
}

Framebuffer makeFramebuffer(const std::string& name) {
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  glBindFramebuffer(GL_FRAMEBUFFER, id);
  label(GL_FRAMEBUFFER, id, name);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return Framebuffer(id);
}

Renderbuffer makeRenderbuffer(const std::string& name) {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  glBindRenderbuffer(GL_RENDERBUFFER, id);
  label(GL_RENDERBUFFER, id, name);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  return Renderbuffer(id);
}

Query makeQuery(const std::string&) {
  GLuint id = 0;
  glGenQueries(1, &id);
  return Query(id);
}

Sampler makeSampler(const std::string& name) {
  GLuint id = 0;
  glGenSamplers(1, &id);
  glBindSampler(0, id);
  label(GL_SAMPLER, id, name);
  glBindSampler(0, 0);
  return Sampler(id);
}

void requireComplete(GLenum target, const std::string& name) {
  const GLenum status = glCheckFramebufferStatus(target);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer '" + name + "' is incomplete (status 0x" + [&] {
      char b[16];
      std::snprintf(b, sizeof b, "%04X", status);
      return std::string(b);
    }() + ")");
}

namespace {
int g_drawCalls = 0;
}
void countDraws(int n) { g_drawCalls += n; }
int drawCalls() { return g_drawCalls; }
void resetDrawCalls() { g_drawCalls = 0; }

RenderTarget makeRenderTarget(int width, int height, const std::string& name) {
  RenderTarget rt;
  rt.width = width;
  rt.height = height;
  rt.color = makeTexture(GL_TEXTURE_2D, name + ".color");
  glBindTexture(GL_TEXTURE_2D, rt.color.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  rt.depthStencil = makeTexture(GL_TEXTURE_2D, name + ".depth");
  glBindTexture(GL_TEXTURE_2D, rt.depthStencil.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, width, height, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  rt.fbo = makeFramebuffer(name);
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, rt.fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rt.color.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, rt.depthStencil.id(), 0);
  requireComplete(GL_FRAMEBUFFER, name);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return rt;
}

}  // namespace shadowlab::gl

#pragma once
// Thin RAII over GL object names: one owner, move-only, deleted with the object, and a debug label
// on every one (visible in RenderDoc and in KHR_debug messages). The GL calls that ARE a lesson
// (binding, drawing, state) stay in the lessons; this only removes the bookkeeping.
#include <string>
#include <utility>

#include "gl/gl.hpp"

namespace shadowlab::gl {

template <class Traits>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Traits::destroy(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
struct BufferTraits {
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayTraits {
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct TextureTraits {
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferTraits {
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct QueryTraits {
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct SamplerTraits {
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct ProgramTraits {
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderTraits {
  static void destroy(GLuint id) { glDeleteShader(id); }
};
}  // namespace detail

using Buffer = Handle<detail::BufferTraits>;
using VertexArray = Handle<detail::VertexArrayTraits>;
using Texture = Handle<detail::TextureTraits>;
using Framebuffer = Handle<detail::FramebufferTraits>;
using Renderbuffer = Handle<detail::RenderbufferTraits>;
using Query = Handle<detail::QueryTraits>;
using Sampler = Handle<detail::SamplerTraits>;
using ProgramHandle = Handle<detail::ProgramTraits>;
using ShaderHandle = Handle<detail::ShaderTraits>;

// Creators: generate, bind once so the object exists (labels need that), label, unbind.
Buffer makeBuffer(GLenum target, const std::string& label);
VertexArray makeVertexArray(const std::string& label);
Texture makeTexture(GLenum target, const std::string& label);
Framebuffer makeFramebuffer(const std::string& label);
Renderbuffer makeRenderbuffer(const std::string& label);
Query makeQuery(const std::string& label);  // labelled on first use (queries exist once begun)
Sampler makeSampler(const std::string& label);

// Draw calls issued since the last reset (the framework resets it every frame and shows it in
// the header and in --bench). Every draw in common/ counts itself; a lesson's own draws call
// countDraws too.
void countDraws(int n = 1);
int drawCalls();
void resetDrawCalls();

// A colour + depth-stencil render target (the headless "window", A/B halves, G-buffers).
struct RenderTarget {
  Framebuffer fbo;
  Texture color;         // GL_RGBA8
  Texture depthStencil;  // GL_DEPTH24_STENCIL8 (a texture so passes can sample it)
  int width = 0, height = 0;
};
RenderTarget makeRenderTarget(int width, int height, const std::string& label);
// Throws std::runtime_error naming `label` and the status when incomplete.
void requireComplete(GLenum target, const std::string& label);

}  // namespace shadowlab::gl

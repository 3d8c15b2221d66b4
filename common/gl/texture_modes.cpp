#include "gl/texture_modes.hpp"

#include <algorithm>
#include <stdexcept>

#include "gl/caps.hpp"

namespace shadowlab::gl {

GLenum wrapEnum(sampling::Wrap wrap) {
  switch (wrap) {
    case sampling::Wrap::Repeat: return GL_REPEAT;
    case sampling::Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case sampling::Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case sampling::Wrap::ClampToBorder:  // WebGL2: to the edge, and the shader paints the border
      return caps().clampToBorder ? GL_CLAMP_TO_BORDER : GL_CLAMP_TO_EDGE;
  }
  return GL_REPEAT;
}

GLenum magFilterEnum(sampling::Filter mag) { return mag == sampling::Filter::Nearest ? GL_NEAREST : GL_LINEAR; }

GLenum minFilterEnum(sampling::Filter min, sampling::MipFilter mip) {
  const bool nearest = min == sampling::Filter::Nearest;
  switch (mip) {
    case sampling::MipFilter::None: return nearest ? GL_NEAREST : GL_LINEAR;
    case sampling::MipFilter::Nearest: return nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_NEAREST;
    case sampling::MipFilter::Linear: return nearest ? GL_NEAREST_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

namespace {
std::vector<std::uint8_t> rgba8(const ImageF& img) { return sampling::toImage8(img).data; }
}  // namespace

Texture uploadMipChain(const std::vector<ImageF>& chain, const std::string& label) {
  if (chain.empty()) throw std::invalid_argument("uploadMipChain: empty chain for " + label);
  if (const std::string problem = textureSizeProblem(chain[0].width, chain[0].height); !problem.empty())
    throw std::runtime_error("texture '" + label + "': " + problem);
  Texture tex = makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t l = 0; l < chain.size(); ++l) {
    const std::vector<std::uint8_t> texels = rgba8(chain[l]);
    glTexImage2D(GL_TEXTURE_2D, GLint(l), GL_RGBA8, chain[l].width, chain[l].height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(chain.size()) - 1);
  glBindTexture(GL_TEXTURE_2D, 0);
  return tex;
}

Texture uploadLevel(const ImageF& image, const std::string& label) {
  Texture tex = makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<std::uint8_t> texels = rgba8(image);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return tex;
}

void updateLevel(GLuint texture, const Image8& image) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.data.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

Texture uploadVolume(int n, const std::vector<std::uint8_t>& voxels, const std::string& label) {
  if (n < 1 || voxels.size() != std::size_t(n) * n * n * 4)
    throw std::invalid_argument("uploadVolume: " + label + " needs n^3 RGBA voxels");
  Texture tex = makeTexture(GL_TEXTURE_3D, label);
  glBindTexture(GL_TEXTURE_3D, tex.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, n, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, voxels.data());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_3D, 0);
  return tex;
}

FilterTexture uploadFilterTexture(const ImageF& base, const std::string& label) {
  FilterTexture t;
  t.chain = sampling::buildMipChain(base);
  t.mips = uploadMipChain(t.chain, label);
  sampling::RipAtlas rip = sampling::buildRipAtlas(base);
  t.rip = uploadLevel(rip.atlas, label + " RIP atlas");
  t.ripOffsetX = std::move(rip.offsetX);
  t.ripOffsetY = std::move(rip.offsetY);
  return t;
}

void setRipUniforms(const Program& program, const FilterTexture& t) {
  glUniform2i(program.location("uTexSize"), t.chain[0].width, t.chain[0].height);
  const GLint levels[2] = {GLint(t.ripOffsetX.size()), GLint(t.ripOffsetY.size())};
  glUniform1iv(program.location("uRipLevels"), 2, levels);
  glUniform1iv(program.location("uRipOffsetX"), GLsizei(t.ripOffsetX.size()), t.ripOffsetX.data());
  glUniform1iv(program.location("uRipOffsetY"), GLsizei(t.ripOffsetY.size()), t.ripOffsetY.data());
}

float applySamplerState(GLuint sampler, const sampling::SamplerState& s) {
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GLint(wrapEnum(s.wrapS)));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GLint(wrapEnum(s.wrapT)));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_R, GLint(wrapEnum(s.wrapS)));
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GLint(magFilterEnum(s.mag)));
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GLint(minFilterEnum(s.min, s.mip)));
  if (caps().clampToBorder) glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, &s.border.x);
  if (!caps().gles) glSamplerParameterf(sampler, GL_TEXTURE_LOD_BIAS, s.lodBias);  // ES: the shader's bias
  float aniso = 1.0f;
  if (caps().anisotropic) {
    aniso = std::clamp(s.maxAniso, 1.0f, caps().maxAnisotropy);
    glSamplerParameterf(sampler, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
  }
  return aniso;
}

FootprintTarget makeFootprintTarget(int width, int height, bool aux, const std::string& label) {
  FootprintTarget t;
  t.width = width;
  t.height = height;
  t.fbo = makeFramebuffer(label);
  glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
  auto attach = [&](Texture& tex, GLenum internal, GLenum type, int index, const std::string& name) {
    tex = makeTexture(GL_TEXTURE_2D, label + " " + name);
    glBindTexture(GL_TEXTURE_2D, tex.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), width, height, 0, GL_RGBA, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + index), GL_TEXTURE_2D, tex.id(), 0);
  };
  attach(t.color, GL_RGBA8, GL_UNSIGNED_BYTE, 0, "colour");
  if (aux) {
    attach(t.uv, GL_RGBA32F, GL_FLOAT, 1, "uv");
    attach(t.derivatives, GL_RGBA32F, GL_FLOAT, 2, "derivatives");
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  t.depth = makeRenderbuffer(label + " depth");
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth.id());
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(aux ? 3 : 1, buffers);
  requireComplete(GL_FRAMEBUFFER, label);
  return t;
}

void clearFootprintTarget(const FootprintTarget& t, const glm::vec3& background) {
  glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
  glViewport(0, 0, t.width, t.height);
  const float zero[4] = {0, 0, 0, 0}, colour[4] = {background.x, background.y, background.z, 1};
  glClearBufferfv(GL_COLOR, 0, colour);
  if (t.uv) {
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_COLOR, 2, zero);
  }
  glClear(GL_DEPTH_BUFFER_BIT);
}

std::vector<glm::vec4> readFloatPixels(GLuint fbo, int attachment, int x, int y, int width, int height) {
  std::vector<glm::vec4> out(std::size_t(width) * height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(x, y, width, height, GL_RGBA, GL_FLOAT, out.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  return out;
}

}  // namespace shadowlab::gl

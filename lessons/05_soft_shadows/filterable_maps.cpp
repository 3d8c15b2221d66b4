#include "filterable_maps.hpp"

#include "algorithms/moment_maps.hpp"
#include "technique/map_pass.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {
gl::Texture floatTexture(GLenum internal, int size, const std::string& label) {
  gl::Texture t = gl::makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // filterable: the point of it
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

gl::Framebuffer colourFbo(const gl::Texture& colour, const gl::Renderbuffer* depth, const std::string& label) {
  gl::Framebuffer f = gl::makeFramebuffer(label);
  glBindFramebuffer(GL_FRAMEBUFFER, f.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.id(), 0);
  if (depth) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth->id());
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
  glDrawBuffers(1, buffers);
  gl::requireComplete(GL_FRAMEBUFFER, label);
  return f;
}
}  // namespace

namespace {
const char* kindName(FilterableMaps::Kind k) {
  constexpr const char* names[] = {"vsm", "esm", "evsm2", "evsm4", "msm"};
  return names[int(k)];
}
}  // namespace

FilterableMaps::FilterableMaps(Kind kind, FilterableParams defaults)
    : kind_(kind),
      p_(defaults),
      maps_(kindName(kind), defaults.maps),
      casters_(std::string(kindName(kind)) + ": moments pass", "common/depth.vert", "uLightViewProj",
               "05_soft_shadows/depth_moments.frag") {}

std::string FilterableMaps::name() const { return kindName(kind_); }

void FilterableMaps::declare(ParamRegistry& r, const std::string& n) {
  r.add(n + "blur", &p_.blur, 0, 16, "Gaussian blur radius in texels: the one penumbra width it gives");
  if (kind_ == Kind::Esm) {
    r.add(n + "exponent", &p_.exponent, 1, 88, "c of exp(c t): sharper and more overflow-prone as it grows");
  } else {
    if (kind_ != Kind::Msm) r.add(n + "min_variance", &p_.minVariance, 0, 0.001f, "variance floor: depth precision");
    r.add(n + "bleed", &p_.bleed, 0, 0.95f, "light-bleeding reduction: cut this share of the bound's tail");
  }
  if (kind_ == Kind::Evsm2 || kind_ == Kind::Evsm4)
    r.add(n + "positive", &p_.evsmPositive, 1, float(soft::kEvsmMaxExponent),
          "c+ of exp(c+ t'): the far receivers' bound tightens as it grows (42: a 32-bit float's limit)");
  if (kind_ == Kind::Evsm4)
    r.add(n + "negative", &p_.evsmNegative, 1, float(soft::kEvsmMaxExponent),
          "c- of -exp(-c- t'): the second warp, for receivers between casters");
  if (kind_ == Kind::Msm) {
    r.addChoice(n + "format", &p_.msmFormat, {"32f", "16"},
                "32-bit float moments, or the paper's optimised 16-bit quantisation (8 bytes a texel, as VSM)");
    r.add(n + "bias", &p_.momentBias, 0, 0.01f, "moment bias alpha: the moments pulled toward 0.5 (3e-5 for 16 bits)");
  }
  r.add(n + "reuse_maps", &p_.reuseMaps, "keep the moments while nothing they depend on changes (a still light)");
  maps_.declare(r, n, false);  // the moments are drawn by its own pass
}

void FilterableMaps::init() {
  maps_.init();
  casters_.build();
  blur_.build();
  vao_ = gl::makeVertexArray("filterable maps: fullscreen");
  dummy_ = floatTexture(GL_RG32F, 1, "filterable maps: none");
  const float far[2] = {1.0f, 1.0f};  // VSM: everything at t = 1; ESM reads exp(c) * exp(-c t) >= 1
  glBindTexture(GL_TEXTURE_2D, dummy_.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, far);
  glBindTexture(GL_TEXTURE_2D, 0);
}

std::vector<std::string> FilterableMaps::shaderDefines() const {
  switch (kind_) {
    case Kind::Esm: return {"ESM"};
    case Kind::Evsm2: return {"EVSM"};
    case Kind::Evsm4: return {"EVSM", "EVSM_FOUR"};
    case Kind::Msm: return msm16() ? std::vector<std::string>{"MSM", "MSM16"} : std::vector<std::string>{"MSM"};
    case Kind::Vsm: break;
  }
  return {};
}

GLenum FilterableMaps::textureFormat() const {
  switch (kind_) {
    case Kind::Esm: return GL_R32F;
    case Kind::Evsm4: return GL_RGBA32F;
    case Kind::Msm: return msm16() ? GL_RGBA16 : GL_RGBA32F;
    case Kind::Vsm:
    case Kind::Evsm2: break;
  }
  return GL_RG32F;
}

int FilterableMaps::bytesPerTexel() const {
  switch (textureFormat()) {
    case GL_R32F: return 4;
    case GL_RGBA32F: return 16;
    default: return 8;  // RG32F, RGBA16
  }
}

glm::vec4 FilterableMaps::farMoments() const {
  switch (kind_) {
    case Kind::Esm: return glm::vec4(std::exp(p_.exponent), 0, 0, 0);
    case Kind::Evsm2:
    case Kind::Evsm4: return glm::vec4(soft::evsmMoments(1.0, p_.evsmPositive, p_.evsmNegative));
    case Kind::Msm: return glm::vec4(msm16() ? soft::msmQuantise(soft::msmMoments(1.0)) : soft::msmMoments(1.0));
    case Kind::Vsm: break;
  }
  return glm::vec4(1.0f, 1.0f, 0.0f, 0.0f);
}

void FilterableMaps::ensure(Target& t, int size, const std::string& label) {
  const GLenum format = textureFormat();
  if (t.fbo && t.size == size && t.format == format) return;
  t.moments = floatTexture(format, size, label + " moments");
  t.scratch = floatTexture(format, size, label + " blur scratch");
  t.depth = gl::makeRenderbuffer(label + " depth");
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  t.fbo = colourFbo(t.moments, &t.depth, label + " fbo");
  t.scratchFbo = colourFbo(t.scratch, nullptr, label + " blur fbo");
  t.size = size;
  t.format = format;
}

// Separable: along x into the scratch texture, along y back into the moments.
void FilterableMaps::blur(Target& t) {
  if (p_.blur <= 0) return;
  glDisable(GL_DEPTH_TEST);
  blur_.use();
  blur_.set("uSource", 0);
  blur_.set("uRadius", p_.blur);
  glBindVertexArray(vao_.id());
  glActiveTexture(GL_TEXTURE0);
  const struct {
    const gl::Framebuffer& into;
    const gl::Texture& from;
    glm::vec2 direction;
  } passes[] = {{t.scratchFbo, t.moments, {1.0f / float(t.size), 0.0f}},
                {t.fbo, t.scratch, {0.0f, 1.0f / float(t.size)}}};
  for (const auto& pass : passes) {
    glBindFramebuffer(GL_FRAMEBUFFER, pass.into.id());
    glBindTexture(GL_TEXTURE_2D, pass.from.id());
    blur_.set("uDirection", pass.direction);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

void FilterableMaps::render(const ShadowContext& c) {
  stats_ = {};
  maps_.render(c, {glm::vec3(0.0f)}, stats_, false);
  const int size = maps_.mapSize();
  const auto& lights = maps_.lights();
  glBindSampler(0, 0);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (!lights[i].on) continue;
    Target& target = targets_[i];
    ensure(target, size, name() + " light" + std::to_string(i));
    stats_.culledCasters += lights[i].centre.culled;
    stats_.bytes += std::uint64_t(size) * std::uint64_t(size) * std::uint64_t(bytesPerTexel()) * 2 + 4ull * size * size;
    // What the moments depend on: the scene, the camera and its casters, the depth range, the
    // kind's exponents or format, the blur.
    PassKey key;
    key << c.scene.revision() << size << lights[i].nearZ << lights[i].farZ << p_.exponent << p_.evsmPositive
        << p_.evsmNegative << p_.msmFormat << p_.blur << lights[i].centre.viewProj()
        << std::span<const char>(lights[i].centre.casters);
    const MapPass pass(c, stats_, int(i), p_.reuseMaps, std::move(key), target.rendered, target.drawn);
    if (!pass.draw()) continue;
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
    glViewport(0, 0, size, size);
    const glm::vec4 far = farMoments();  // t = 1: nothing in front
    glClearColor(far.x, far.y, far.z, far.w);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    casters_.setUniforms([&](const gl::Program& p) {
      p.set("uDepthRange", glm::vec2(lights[i].nearZ, lights[i].farZ));
      p.set("uExponent", p_.exponent);
      p.set("uKind", int(kind_));
      p.set("uEvsm", glm::vec2(std::min(p_.evsmPositive, float(soft::kEvsmMaxExponent)),
                               std::min(p_.evsmNegative, float(soft::kEvsmMaxExponent))));
      p.set("uMsm16", msm16());
    });
    stats_.triangles += casters_.draw(c.scene, lights[i].centre.viewProj(), lights[i].centre.casters, {true, false});
    blur(target);
    stats_.texels += std::uint64_t(size) * std::uint64_t(size);
  }
  glClearColor(0, 0, 0, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
  stats_.extra.push_back(
      {"blur", std::to_string(2 * p_.blur + 1) + " taps per direction, " + std::to_string(size) + "^2"});
}

void FilterableMaps::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  lit.set("uMinVariance", p_.minVariance);
  lit.set("uBleed", std::min(p_.bleed, 0.95f));
  lit.set("uExponent", p_.exponent);
  lit.set("uEvsm", glm::vec2(std::min(p_.evsmPositive, float(soft::kEvsmMaxExponent)),
                             std::min(p_.evsmNegative, float(soft::kEvsmMaxExponent))));
  lit.set("uMomentBias", p_.momentBias);
  const auto& lights = maps_.lights();
  for (int i = 0; i < kMaxLights; ++i) {
    const int unit = firstUnit + 2 + i;
    const bool on = i < int(lights.size()) && lights[std::size_t(i)].on && targets_[std::size_t(i)].fbo;
    lit.set(("uMoments[" + std::to_string(i) + "]").c_str(), unit);
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, on ? targets_[std::size_t(i)].moments.id() : dummy_.id());
    glBindSampler(GLuint(unit), 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

void FilterableMaps::unbindVisibility(int firstUnit) const { maps_.unbind(firstUnit); }

}  // namespace shadowlab::tech

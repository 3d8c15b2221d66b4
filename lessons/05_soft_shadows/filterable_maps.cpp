#include "filterable_maps.hpp"

#include "algorithms/moment_maps.hpp"
#include "gl/caps.hpp"
#include "technique/map_pass.hpp"
#include "technique/map_settings.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {
// The channels a moment format holds, as glTexImage2D names them (OpenGL ES wants them to match).
GLenum channels(GLenum internal) {
  switch (internal) {
    case GL_R32F:
    case GL_R16F: return GL_RED;
    case GL_RG32F:
    case GL_RG16F: return GL_RG;
    default: return GL_RGBA;
  }
}

gl::Texture floatTexture(GLenum internal, glm::ivec2 size, const std::string& label) {
  gl::Texture t = gl::makeTexture(GL_TEXTURE_2D, label);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), size.x, size.y, 0, channels(internal),
               internal == GL_RGBA16 ? GL_UNSIGNED_SHORT : GL_FLOAT, nullptr);
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
  maps_.setCubeCheck([this](int size) { return cubeRefusal(size); });
  casters_.build();
  blur_.build();
  vao_ = gl::makeVertexArray("filterable maps: fullscreen");
  dummy_ = floatTexture(storedFormat(GL_RG32F), {1, 1}, "filterable maps: none");
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

// The format the moments are stored in: textureFormat(), or what this context can render into and
// filter instead (WebGL2 without EXT_color_buffer_float or OES_texture_float_linear: 16-bit floats;
// without EXT_texture_norm16: the 16-bit quantised moments in 32-bit floats). formatNote() says so.
GLenum FilterableMaps::storedFormat(GLenum format) {
  const gl::Caps& caps = gl::caps();
  if (format == GL_RGBA16 && !caps.norm16) format = GL_RGBA32F;
  if (caps.floatColorBuffers && caps.floatLinear) return format;
  switch (format) {
    case GL_R32F: return GL_R16F;
    case GL_RG32F: return GL_RG16F;
    case GL_RGBA32F: return GL_RGBA16F;
    default: return format;
  }
}

// The exponents the stored format holds: a 32-bit float's (ESM's c <= 88; EVSM's <= 42, its square
// too) or, in the 16-bit fallback, a half float's (65504 = e^11.09: ESM's c <= 11, EVSM's <= 5.5).
bool FilterableMaps::halfFloats() const {
  const GLenum f = storedFormat(textureFormat());
  return f == GL_R16F || f == GL_RG16F || f == GL_RGBA16F;
}
float FilterableMaps::esmExponent() const { return std::min(p_.exponent, halfFloats() ? 11.0f : 88.0f); }
glm::vec2 FilterableMaps::evsmExponents() const {
  const float most = halfFloats() ? 5.5f : float(soft::kEvsmMaxExponent);
  return {std::min(p_.evsmPositive, most), std::min(p_.evsmNegative, most)};
}

std::string FilterableMaps::formatNote() const {
  const GLenum wanted = textureFormat(), stored = storedFormat(wanted);
  if (stored == wanted) return "";
  const auto name = [](GLenum f) {
    switch (f) {
      case GL_R32F: return "R32F";
      case GL_RG32F: return "RG32F";
      case GL_RGBA32F: return "RGBA32F";
      case GL_R16F: return "R16F";
      case GL_RG16F: return "RG16F";
      case GL_RGBA16F: return "RGBA16F";
      default: return "RGBA16";
    }
  };
  const gl::Caps& caps = gl::caps();
  const char* why = wanted == GL_RGBA16 && !caps.norm16 ? "no EXT_texture_norm16"
                    : !caps.floatColorBuffers           ? "no EXT_color_buffer_float"
                                                        : "no OES_texture_float_linear";
  std::string note = std::string(name(stored)) + " instead of " + name(wanted) + " (" + why + ")";
  if (kind_ == Kind::Esm && esmExponent() < p_.exponent)
    note += ", exponent " + std::to_string(int(esmExponent())) + " (a half float's largest)";
  if ((kind_ == Kind::Evsm2 || kind_ == Kind::Evsm4) && evsmExponents() != glm::vec2(p_.evsmPositive, p_.evsmNegative))
    note += ", exponents at most 5.5 (a half float's largest square)";
  return note;
}

int FilterableMaps::bytesPerTexel() const {
  switch (storedFormat(textureFormat())) {
    case GL_R32F: return 4;
    case GL_R16F: return 2;
    case GL_RGBA32F: return 16;
    case GL_RG16F: return 4;
    default: return 8;  // RG32F, RGBA16, RGBA16F
  }
}

glm::vec4 FilterableMaps::farMoments() const {
  switch (kind_) {
    case Kind::Esm: return glm::vec4(std::exp(esmExponent()), 0, 0, 0);
    case Kind::Evsm2:
    case Kind::Evsm4: return glm::vec4(soft::evsmMoments(1.0, evsmExponents().x, evsmExponents().y));
    case Kind::Msm: return glm::vec4(msm16() ? soft::msmQuantise(soft::msmMoments(1.0)) : soft::msmMoments(1.0));
    case Kind::Vsm: break;
  }
  return glm::vec4(1.0f, 1.0f, 0.0f, 0.0f);
}

void FilterableMaps::ensure(Target& t, int size, int faces, const std::string& label) {
  const GLenum format = storedFormat(textureFormat());
  const glm::ivec2 extent = atlasExtent(size, faces);
  if (t.fbo && t.size == size && t.faces == faces && t.format == format) return;
  t.moments = floatTexture(format, extent, label + " moments");
  t.scratch = floatTexture(format, extent, label + " blur scratch");
  t.depth = gl::makeRenderbuffer(label + " depth");
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, extent.x, extent.y);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  t.fbo = colourFbo(t.moments, &t.depth, label + " fbo");
  t.scratchFbo = colourFbo(t.scratch, nullptr, label + " blur fbo");
  t.size = size;
  t.faces = faces;
  t.format = format;
}

// One face: size^2; a cube's six: a 3 x 2 atlas of faces (face f at column f % 3, row f / 3).
glm::ivec2 FilterableMaps::atlasExtent(int size, int faces) {
  return faces == 6 ? glm::ivec2(3, 2) * size : glm::ivec2(size);
}

// A cube's atlas must fit a texture's side and the budget of one light's maps (the moments, the
// blur's scratch and the depth buffer).
std::string FilterableMaps::cubeRefusal(int size) const {
  const glm::ivec2 extent = atlasExtent(size, 6);
  const std::uint64_t bytes =
      std::uint64_t(extent.x) * std::uint64_t(extent.y) * std::uint64_t(2 * bytesPerTexel() + 4);
  const int most = gl::caps().maxTextureSize;
  if (most > 0 && extent.x > most) {
    int fits = kMapSizes.front();
    for (int s : kMapSizes)
      if (3 * s <= most) fits = s;
    return "a cube's 3 x 2 atlas of " + std::to_string(size) + "^2 faces is " + std::to_string(extent.x) +
           " texels wide, over this context's " + std::to_string(most) + " (map_size " + std::to_string(fits) +
           " at most)";
  }
  if (bytes > SoftMaps::kBudgetBytes)
    return "a cube's 3 x 2 atlas of " + std::to_string(size) + "^2 faces takes " + std::to_string(bytes >> 20) +
           " MiB, over the " + std::to_string(SoftMaps::kBudgetBytes >> 20) + " MiB budget of one light's maps";
  return "";
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
  } passes[] = {{t.scratchFbo, t.moments, {1.0f / float(atlasExtent(t.size, t.faces).x), 0.0f}},
                {t.fbo, t.scratch, {0.0f, 1.0f / float(atlasExtent(t.size, t.faces).y)}}};
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
  const shadow::CasterBoxes boxes = c.scene.casterBoxes();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const SoftLight& light = lights[i];
    if (!light.on) continue;
    Target& target = targets_[i];
    ensure(target, size, light.faces, name() + " light" + std::to_string(i));
    // One camera, or a cube's six (each face a tile of the atlas).
    std::vector<shadow::LightCamera> cameras;
    for (int f = 0; f < light.faces; ++f)
      cameras.push_back(light.faces == 1 ? light.centre : SoftMaps::faceCamera(light, f, light.spot.position, boxes));
    const glm::ivec2 extent = atlasExtent(size, light.faces);
    stats_.bytes += std::uint64_t(extent.x) * std::uint64_t(extent.y) * (std::uint64_t(bytesPerTexel()) * 2 + 4);
    // What the moments depend on: the scene, the cameras and their casters, the depth range, the
    // kind's exponents or format, the blur.
    PassKey key;
    key << c.scene.revision() << size << light.nearZ << light.farZ << p_.exponent << p_.evsmPositive << p_.evsmNegative
        << p_.msmFormat << p_.blur;
    for (const shadow::LightCamera& camera : cameras) {
      key << camera.viewProj() << std::span<const char>(camera.casters);
      stats_.culledCasters += camera.culled;
    }
    const MapPass pass(c, stats_, int(i), p_.reuseMaps, std::move(key), target.rendered, target.drawn);
    if (!pass.draw()) continue;
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
    glViewport(0, 0, extent.x, extent.y);
    const glm::vec4 far = farMoments();  // t = 1: nothing in front
    glClearColor(far.x, far.y, far.z, far.w);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    casters_.setUniforms([&](const gl::Program& p) {
      p.set("uDepthRange", glm::vec2(light.nearZ, light.farZ));
      p.set("uExponent", esmExponent());
      p.set("uKind", int(kind_));
      p.set("uEvsm", evsmExponents());
      p.set("uMsm16", msm16());
    });
    for (int f = 0; f < light.faces; ++f) {
      glViewport((f % 3) * size, (f / 3) * size, size, size);
      stats_.triangles +=
          casters_.draw(c.scene, cameras[std::size_t(f)].viewProj(), cameras[std::size_t(f)].casters, {true, false});
      stats_.texels += std::uint64_t(size) * std::uint64_t(size);
    }
    glViewport(0, 0, extent.x, extent.y);
    blur(target);
  }
  glClearColor(0, 0, 0, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glViewport(0, 0, c.frame.width, c.frame.height);
  stats_.extra.push_back(
      {"blur", std::to_string(2 * p_.blur + 1) + " taps per direction, " + std::to_string(size) + "^2"});
  if (const std::string note = formatNote(); !note.empty()) stats_.extra.push_back({"moments", note});
}

void FilterableMaps::bindVisibility(const gl::Program& lit, int firstUnit) const {
  maps_.bind(lit, firstUnit);
  lit.set("uMinVariance", p_.minVariance);
  lit.set("uBleed", std::min(p_.bleed, 0.95f));
  lit.set("uExponent", esmExponent());
  lit.set("uEvsm", evsmExponents());
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

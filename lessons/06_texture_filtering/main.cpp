// Lesson 06: texture filtering, from texels to anisotropy ([Tarantsev-L12], textures). A ground plane to
// the horizon, a tunnel and a sphere, textured with patterns that alias; every filter of the
// lecture on a GL sampler object: wrap modes, nearest/linear magnification, the four mipmap modes,
// trilinear, anisotropic 1x-16x, LOD bias; RIP maps filtered in the shader; texture coordinates
// explicit or projected (planar, cylindrical, spherical); replace/modulate/blend per channel;
// normal maps under a moving light; a slice of a 3D texture. Under the cursor (probe.x/probe.y
// headless): the footprint, lambda and the anisotropic probes, from the CPU and from the shader.
// A CPU reference sampler (algorithms/texture_sampling) renders the same footprints for a difference view.
//
// Controls: left drag orbit, right drag pan, wheel zoom; F filter preset cycle (filter.mip), M mag,
// V view, N normal map, L light animation, P camera path; F1 help.
// Exercises (exercises.hpp): mip count and memory, LOD, bilinear, trilinear, anisotropic probes,
// box downsample. `--set impl=student --set view=cpu_reference` samples with your code.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include "app/exercise_program.hpp"
#include "app/footprint_reference.hpp"
#include "app/lesson.hpp"
#include "core/mesh_gen.hpp"
#include "core/paths.hpp"
#include "algorithms/texture_sampling.hpp"
#include "exercises.hpp"
#include "gl/caps.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "gl/texture_modes.hpp"

using namespace shadowlab;
using sampling::Filter;
using sampling::MipFilter;
using sampling::Wrap;

namespace {

enum class SceneKind { Ground, Tunnel, Sphere };
enum class TexChoice { CheckerFine, Checker, Text, Bricks, ZonePlate, Volume };
enum class UvMode { Auto, Explicit, Planar, Cylindrical, Spherical };
enum class View { Shaded, MipLevel, Anisotropy, CpuReference, Difference };
enum class Sampling { Hardware, RipMap };
enum class Combine { Replace, Modulate, Blend };
enum class Channels { Rgb, Luminance, Alpha };

struct Params {
  SceneKind scene = SceneKind::Ground;         // a plane to the horizon shows every LOD at once
  TexChoice texture = TexChoice::CheckerFine;  // fine detail is what aliases
  UvMode uv = UvMode::Auto;                    // auto: the scene's natural projection
  float uvScale = 0.25f;                       // tiling: repeats per unit (ground: a tile every 4 m)
  Filter mag = Filter::Linear;                 // texel larger than a pixel
  Filter min = Filter::Linear;                 // texel smaller than a pixel, within a level
  MipFilter mip = MipFilter::Linear;           // between levels: none, nearest level, blend two
  int aniso = 1;                               // EXT_texture_filter_anisotropic's max anisotropy
  float lodBias = 0.0f;                        // added to lambda: + blurs, - sharpens (and aliases)
  Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
  glm::vec3 border{1.0f, 0.2f, 0.6f};      // clamp-to-border colour (visible on purpose)
  Sampling sampling = Sampling::Hardware;  // or RIP maps, filtered in the fragment shader
  View view = View::Shaded;
  Combine combine = Combine::Modulate;  // how the texture meets the lit material
  Channels channels = Channels::Rgb;
  glm::vec3 envColor{1.0f, 0.8f, 0.2f};  // blend's constant colour C_c
  bool normalMap = false;                // bricks_normal.png perturbs N (light it from the side)
  bool animateLight = true;              // the light orbits: normal maps need a moving light
  float lightAngle = 0.8f;
  float slice = 0.5f;              // r of the 3D texture slice
  int volumeSize = 1;              // 32, 64, 128, 256 voxels a side
  bool path = false;               // scripted sideways camera move (deterministic headless)
  float pathSpeed = 0.35f;         // metres a second
  int probeX = 640, probeY = 560;  // pixel under the readout (the mouse when windowed)
  bool measure = false;            // supersampled reference each frame; prints error lines
  int supersample = 4;             // reference pixels per pixel, per axis
  Impl impl = Impl::Reference;     // student: the CPU view samples with exercises.cpp
  float diffGain = 8.0f;           // difference view amplification
};

const char* const kTextureFiles[] = {"checker_fine.png", "checker.png", "text.png", "bricks.png"};
constexpr int kVolumeSizes[] = {32, 64, 128, 256};

double mib(std::uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }
std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Texels and pixels: wrap modes, magnification, the four mipmap modes, trilinear, anisotropic, RIP "
    "maps, normal maps.";
const char* const kHelp = R"(Look at the ground plane near the horizon: that is minification.
Try: filter.mip=none with filter.min=nearest (moire), then trilinear, then filter.aniso=16;
view=mip_level colours the level per pixel; the header shows lambda and the anisotropic
probes under the cursor; view=difference compares the GPU with the CPU reference sampler.)";

}  // namespace

// The colour key of the mip-level and anisotropy views: levelColour() of scene.frag, as drawn.
Legend levelLegend(View view) {
  static const glm::vec3 palette[8] = {{0.2f, 0.2f, 1.0f}, {0.0f, 0.8f, 1.0f}, {0.0f, 0.9f, 0.3f}, {0.8f, 1.0f, 0.0f},
                                       {1.0f, 0.7f, 0.0f}, {1.0f, 0.2f, 0.0f}, {0.9f, 0.0f, 0.6f}, {1.0f, 1.0f, 1.0f}};
  const auto colour = [](float level) {
    const float l = std::clamp(level, 0.0f, 7.0f);
    const int i = int(l);
    return glm::mix(palette[i], palette[std::min(i + 1, 7)], l - float(i));
  };
  Legend key{view == View::MipLevel ? "mip level the hardware picks" : "anisotropic probes N", {}};
  for (int i = 0; i < (view == View::MipLevel ? 8 : 5); ++i)
    key.entries.push_back(view == View::MipLevel
                              ? Legend::Entry{colour(float(i)), "level " + std::to_string(i) + (i == 7 ? "+" : "")}
                              : Legend::Entry{colour(float(i) * 1.75f), "N = " + std::to_string(1 << i)});
  return key;
}

class TextureFilteringLesson : public Lesson {
 public:
  void declare(ParamRegistry& r) override {
    camera.aim({0, 1, 0}, 4.0f, 0.12f);  // low over the ground plane: every LOD to the horizon
    camera.farZ = 500.0f;
    r.addChoice("scene", &p_.scene, {"ground", "tunnel", "sphere"}, "a plane to the horizon, a tunnel, a sphere")
        .hotkey = "G";
    r.addChoice("texture", &p_.texture, {"checker_fine", "checker", "text", "bricks", "zone_plate", "volume"},
                "what is sampled: fine detail aliases; volume is a slice of a 3D texture")
        .hotkey = "T";
    r.addChoice("uv.mode", &p_.uv, {"auto", "explicit", "planar", "cylindrical", "spherical"},
                "texture coordinates: the mesh's own, or projected from the object-space position")
        .hotkey = "U";
    r.add("uv.scale", &p_.uvScale, 0.05f, 64.0f, "tiling: repeats of the texture per unit of uv");
    r.addChoice("filter.mag", &p_.mag, {"nearest", "linear"}, "magnification: the nearest texel, or bilinear").hotkey =
        "M";
    r.addChoice("filter.min", &p_.min, {"nearest", "linear"}, "minification inside one level: nearest or bilinear");
    r.addChoice("filter.mip", &p_.mip, {"none", "nearest", "linear"},
                "between levels: level 0 only, the nearest level, blend two (trilinear)")
        .hotkey = "F";
    r.add("filter.aniso", &p_.aniso, 1, 16, "max anisotropy: up to N probes along the footprint's long axis");
    r.add("filter.lod_bias", &p_.lodBias, -4.0f, 4.0f, "added to lambda: positive blurs, negative aliases");
    const std::vector<std::string> wraps{"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border"};
    r.addChoice("wrap.s", &p_.wrapS, wraps, "what u outside [0,1] reads");
    r.addChoice("wrap.t", &p_.wrapT, wraps, "what v outside [0,1] reads");
    r.addColor("wrap.border", &p_.border, "the clamp-to-border colour");
    r.addChoice("sampling", &p_.sampling, {"hardware", "rip_map"},
                "the GPU's mipmaps, or RIP maps filtered in the shader")
        .hotkey = "I";
    r.addChoice("view", &p_.view, {"shaded", "mip_level", "anisotropy", "cpu_reference", "difference"},
                "colour: the result, the mip level per pixel, the probe count, the CPU sampler, |GPU - CPU|")
        .hotkey = "V";
    r.addChoice("combine", &p_.combine, {"replace", "modulate", "blend"},
                "texture and material: texture only, product, blend to C_c")
        .hotkey = "C";
    r.addChoice("combine.channels", &p_.channels, {"rgb", "luminance", "alpha"},
                "which part of the texture takes part");
    r.addColor("combine.env_color", &p_.envColor, "C_c of the blend mode");
    r.add("normal_map", &p_.normalMap, "perturb the normal with bricks_normal.png").hotkey = "N";
    r.add("light.animate", &p_.animateLight, "orbit the light so the normal map's relief moves").hotkey = "L";
    r.add("light.angle", &p_.lightAngle, -6.3f, 6.3f, "where the light is on its orbit (radians)");
    r.add("volume.slice", &p_.slice, 0.0f, 1.0f, "r coordinate of the 3D texture's slice");
    r.addChoice("volume.size", &p_.volumeSize, {"32", "64", "128", "256"}, "voxels a side: memory grows with the cube");
    r.add("camera.path", &p_.path, "slide the camera sideways (flicker shows on fine detail)").hotkey = "P";
    r.add("camera.path_speed", &p_.pathSpeed, 0.0f, 10.0f, "metres a second along the path");
    r.add("probe.x", &p_.probeX, 0, 8192, "pixel column of the readout (the mouse in a window)");
    r.add("probe.y", &p_.probeY, 0, 8192, "pixel row of the readout, from the top");
    r.add("measure", &p_.measure, "render a supersampled reference each frame and print RMSE and flicker");
    r.add("measure.supersample", &p_.supersample, 2, 8, "reference pixels per pixel, per axis");
    declareImpl(r, &p_.impl, "whose sampler the CPU view uses (student: exercises.cpp)");
    exercises.add("06.1", "mipLevelCount", "");
    exercises.add("06.2", "mipChainBytes", "");
    exercises.add("06.3", "lodFromDerivatives", "view=cpu_reference samples every pixel at lambda 0: aliasing");
    exercises.add("06.4", "sampleBilinear", "");
    exercises.add("06.5", "sampleTrilinear", "view=cpu_reference is black wherever the texture is");
    exercises.add("06.6", "anisotropicProbes", "");
    exercises.add("06.7", "boxDownsample", "");
    exercises.addGlsl("06.8", "ripLevelOfDetail", "sampling=rip_map reads level 0 everywhere: aliasing");
    exercises.addGlsl("06.9", "ripBilinear", "sampling=rip_map is black wherever the texture is");
    r.add("diff_gain", &p_.diffGain, 1.0f, 64.0f, "difference view: |GPU - CPU| times this");
  }

  LessonInfo info() const override { return {"06", "06_texture_filtering", "Texture filtering", kSummary, 2, kHelp}; }

  void init() override {
    program_.build();
    sampler_ = gl::makeSampler("06 filter sampler");
    ground_ = gl::uploadMesh(makePlane(400.0f, 8, 400.0f), "ground plane");
    Mesh tube = makeCylinder(3.0f, 200.0f, 96, false);
    flipInsideOut(tube);
    tunnel_ = gl::uploadMesh(tube, "tunnel");
    sphere_ = gl::uploadMesh(makeSphere(2.0f, 128, 64), "sphere");
    normalMap_ =
        gl::uploadMipChain(sampling::buildMipChain(sampling::toFloat(loadImage(textureRoot() + "/bricks_normal.png"))),
                           "bricks normal map");
    loadTexture();
  }

  void resize(int w, int h) override {
    target_ = gl::makeFootprintTarget(w, h, true, "06 scene target");
    cpuView_.resize(w, h);
    supersampled_.reset();
  }

  void update(const FrameInfo& f) override {
    if (p_.texture != builtTexture_ || p_.volumeSize != builtVolume_) loadTexture();
    if (p_.animateLight) p_.lightAngle = std::remainder(p_.lightAngle + 0.6f * float(f.dt), 6.2831853f);
    if (p_.path) camera.target.x += p_.pathSpeed * float(f.dt);
  }

  void render(const FrameInfo& f) override {
    const float aniso = gl::applySamplerState(sampler_.id(), samplerState());
    // ==== 1. the scene: texture coordinates, filtering, combination =================================
    {
      auto t = scope("scene");
      drawScene(target_, samplerState(), f.width, f.height);
      if (p_.view == View::MipLevel || p_.view == View::Anisotropy) legends.push_back(levelLegend(p_.view));
    }
    // ==== 2. readout under the cursor: footprint, lambda, anisotropic probes =========================
    {
      auto t = scope("probe readout");
      probeReadout(f, aniso);
    }
    // ==== 3. CPU reference sampler and the difference view ==========================================
    const bool cpuView = p_.view == View::CpuReference || p_.view == View::Difference;
    if (cpuView) {
      auto t = scope("cpu reference");
      cpuReference();
    }
    // ==== 4. error against a supersampled reference (the benchmark sweep) ===========================
    if (p_.measure) {
      auto t = scope("supersampled reference");
      measure(f);
    }
    // ==== 5. to the screen, with the probe marked ==================================================
    {
      auto t = scope("present");
      glBindFramebuffer(GL_READ_FRAMEBUFFER, cpuView ? cpuView_.framebuffer() : target_.fbo.id());
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f.framebuffer);
      glBlitFramebuffer(0, 0, f.width, f.height, 0, 0, f.width, f.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer);
      glEnable(GL_SCISSOR_TEST);
      const int px = std::clamp(p_.probeX, 0, f.width - 1), py = f.height - 1 - std::clamp(p_.probeY, 0, f.height - 1);
      glClearColor(1, 0.1f, 0.9f, 1);
      glScissor(px - 8, py, 17, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glScissor(px, py - 8, 1, 17);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
    }
  }

  void gui() override {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || io.MousePos.x < 0 || io.MousePos.y < 0) return;
    p_.probeX = int(io.MousePos.x * io.DisplayFramebufferScale.x);
    p_.probeY = int(io.MousePos.y * io.DisplayFramebufferScale.y);
  }

 private:
  sampling::SamplerState samplerState() const {
    sampling::SamplerState s;
    s.mag = p_.mag;
    s.min = p_.min;
    s.mip = p_.mip;
    s.wrapS = p_.wrapS;
    s.wrapT = p_.wrapT;
    s.border = glm::vec4(p_.border, 1);
    s.lodBias = p_.lodBias;
    s.maxAniso = float(p_.aniso);
    return s;
  }

  // scene.frag's modes (its UV_MODE, VIEW, ... defines, or the generic build's uniforms).
  struct ShaderModes {
    int uvMode, view, sampling, combine, channels;
    bool normalMapping;
  };
  ShaderModes shaderModes() const {
    const bool cpuView = p_.view == View::CpuReference || p_.view == View::Difference;
    return {int(uvMode()) - 1,
            cpuView ? 3 : std::min(int(p_.view), 2),
            p_.texture == TexChoice::Volume ? 2 : int(p_.sampling),
            int(p_.combine),
            int(p_.channels),
            p_.normalMap};
  }

  // The scene's natural projection and its tiling: (repeats along u, along v).
  UvMode uvMode() const {
    if (p_.uv != UvMode::Auto) return p_.uv;
    return p_.scene == SceneKind::Ground   ? UvMode::Planar
           : p_.scene == SceneKind::Tunnel ? UvMode::Cylindrical
                                           : UvMode::Spherical;
  }
  glm::vec2 uvScale() const {
    const UvMode m = uvMode();
    glm::vec2 base(1.0f);
    if (m == UvMode::Cylindrical) base = {16.0f, 1.0f};
    if (m == UvMode::Spherical) base = {8.0f, 4.0f};
    if (m == UvMode::Explicit && p_.scene == SceneKind::Tunnel) base = {16.0f, 200.0f / 18.85f * 16.0f};
    if (m == UvMode::Explicit && p_.scene == SceneKind::Sphere) base = {8.0f, 4.0f};
    return base * p_.uvScale;
  }

  void loadTexture() {
    builtTexture_ = p_.texture;
    builtVolume_ = p_.volumeSize;
    ImageF base = p_.texture == TexChoice::ZonePlate ? sampling::makeZonePlate(512)
                  : p_.texture == TexChoice::Volume
                      ? sampling::makeZonePlate(256)
                      : sampling::toFloat(loadImage(textureRoot() + "/" + kTextureFiles[int(p_.texture)]));
    chain_ = sampling::buildMipChain(base);
    texture_ = gl::uploadMipChain(
        chain_, std::string("06 texture ") + (p_.texture == TexChoice::ZonePlate ? "zone plate" : "file"));
    const sampling::RipAtlas rip = sampling::buildRipAtlas(base);
    rip_ = gl::uploadLevel(rip.atlas, "06 RIP atlas");
    ripOffsetX_ = rip.offsetX;
    ripOffsetY_ = rip.offsetY;
    if (p_.texture == TexChoice::Volume) {  // a "tomogram": nested shells of density
      const int n = kVolumeSizes[p_.volumeSize];
      const std::vector<std::uint8_t> voxels = sampling::makeShellVolume(n);
      volume_ = gl::uploadVolume(n, voxels, "06 volume " + std::to_string(n) + "^3");
    }
  }

  void drawScene(const gl::FootprintTarget& t, const sampling::SamplerState& s, int w, int h) {
    const glm::vec3 sky(0.55f, 0.7f, 0.9f);
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
    glViewport(0, 0, t.width, t.height);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const float zero[4] = {0, 0, 0, 0}, skyColor[4] = {sky.x, sky.y, sky.z, 1};
    glClearBufferfv(GL_COLOR, 0, skyColor);
    if (t.uv) {
      glClearBufferfv(GL_COLOR, 1, zero);
      glClearBufferfv(GL_COLOR, 2, zero);
    }
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::mat4 viewProj = camera.projection(float(w) / float(h)) * camera.view();
    // The modes as the shader's constants: one program per mode set (the generic build, driven by
    // the same values as uniforms, draws while a new one compiles in a window).
    const ShaderModes m = shaderModes();
    gl::Program& program = program_.get(
        {"UV_MODE " + std::to_string(m.uvMode), "VIEW " + std::to_string(m.view),
         "SAMPLING " + std::to_string(m.sampling), "COMBINE " + std::to_string(m.combine),
         "CHANNELS " + std::to_string(m.channels), "NORMAL_MAPPING " + std::to_string(int(m.normalMapping))});
    program.use();
    program.set("uUvMode", m.uvMode);
    program.set("uView", m.view);
    program.set("uSampling", m.sampling);
    program.set("uCombine", m.combine);
    program.set("uChannels", m.channels);
    program.set("uNormalMapping", m.normalMapping);
    program.set("uViewProj", viewProj);
    program.set("uEye", camera.position());
    program.set("uUvScale", uvScale());
    program.set("uEnvColor", p_.envColor);
    program.set("uMaterial", glm::vec3(0.9f, 0.88f, 0.85f));
    program.set("uSky", sky);
    program.set("uLightPos",
                camera.target + glm::vec3(3.0f * std::cos(p_.lightAngle), 1.0f, 3.0f * std::sin(p_.lightAngle)));
    glUniform2i(program.location("uTexSize"), chain_[0].width, chain_[0].height);
    program.set("uLodBias", s.lodBias);
    program.set("uMaxAniso", float(gl::caps().anisotropic ? std::min(s.maxAniso, gl::caps().maxAnisotropy) : 1.0f));
    program.set("uSlice", p_.slice);
    glUniform1iv(program.location("uRipLevels"), 2,
                 std::array<int, 2>{int(ripOffsetX_.size()), int(ripOffsetY_.size())}.data());
    glUniform1iv(program.location("uRipOffsetX"), GLsizei(ripOffsetX_.size()), ripOffsetX_.data());
    glUniform1iv(program.location("uRipOffsetY"), GLsizei(ripOffsetY_.size()), ripOffsetY_.data());
    const GLuint units[4] = {texture_.id(), normalMap_.id(), rip_.id(), volume_.id()};
    const GLenum targets[4] = {GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_3D};
    const char* names[4] = {"uTex", "uNormalMap", "uRip", "uVolume"};
    for (int i = 0; i < 4; ++i) {
      glActiveTexture(GLenum(GL_TEXTURE0 + i));
      glBindTexture(targets[i], units[i]);
      glBindSampler(GLuint(i), i == 2 ? 0 : sampler_.id());  // the lesson's sampler object holds every mode
      program.set(names[i], i);
    }
    glm::mat4 model(1.0f);
    const gl::GpuMesh* mesh = &ground_;
    if (p_.scene == SceneKind::Tunnel) {
      model = glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(1, 0, 0));
      mesh = &tunnel_;
    } else if (p_.scene == SceneKind::Sphere) {
      model = glm::translate(glm::mat4(1), glm::vec3(0, 1, 0));
      mesh = &sphere_;
    }
    program.set("uModel", model);
    program.set("uNormalMatrix", glm::inverseTranspose(glm::mat3(model)));
    mesh->draw();
    for (int i = 3; i >= 0; --i) {
      glActiveTexture(GLenum(GL_TEXTURE0 + i));
      glBindSampler(GLuint(i), 0);
    }
  }

  void probeReadout(const FrameInfo& f, float aniso) {
    const int x = std::clamp(p_.probeX, 0, f.width - 1), y = f.height - 1 - std::clamp(p_.probeY, 0, f.height - 1);
    const glm::vec4 uv = gl::readFloatPixels(target_.fbo.id(), 1, x, y, 1, 1)[0];
    const glm::vec4 d = gl::readFloatPixels(target_.fbo.id(), 2, x, y, 1, 1)[0];
    const glm::ivec2 size(chain_[0].width, chain_[0].height);
    const sampling::Footprint fp = sampling::footprint({d.x, d.y}, {d.z, d.w}, size, aniso);
    const std::uint64_t base = std::uint64_t(size.x) * size.y * 4;
    const int n = kVolumeSizes[p_.volumeSize];
    counters = {
        {"texture", fmt("%.0fx%.0f RGBA8, %.0f levels", size.x, size.y, double(chain_.size()))},
        {"mip chain", fmt("%.3f MiB = %.4f x base (lecture: 1.5)", mib(sampling::mipChainBytes(size.x, size.y, 4)),
                          double(sampling::mipChainBytes(size.x, size.y, 4)) / double(base))},
        {"RIP map", fmt("%.3f MiB = %.4f x base", mib(sampling::ripMapBytes(size.x, size.y, 4)),
                        double(sampling::ripMapBytes(size.x, size.y, 4)) / double(base))},
        {"3D texture", fmt("%.0f^3 x 4 B = %.2f MiB (lecture: 256^3 x 4 = %.0f MiB)", n,
                           mib(sampling::volumeBytes(n, n, n, 4)), mib(sampling::volumeBytes(256, 256, 256, 4)))},
        {"anisotropy", gl::caps().anisotropic ? fmt("%.0fx (max %.0fx)", aniso, gl::caps().maxAnisotropy)
                                              : std::string("extension missing: 1x only")}};
    const std::string at = fmt("(%.0f, %.0f)", p_.probeX, p_.probeY);
    if (uv.z < 0.5f) {
      counters.push_back({"probe " + at, "sky: no texture"});
      return;
    }
    counters.push_back({"probe " + at + " uv", fmt("%.3f, %.3f", uv.x, uv.y)});
    counters.push_back({"probe d(uv)/dx,dy texels",
                        fmt("(%.2f, %.2f) (%.2f, %.2f)", d.x * size.x, d.y * size.y, d.z * size.x, d.w * size.y)});
    counters.push_back({"probe Px, Py", fmt("%.2f, %.2f texels", fp.px, fp.py)});
    counters.push_back({"probe lambda CPU / GPU", fmt("%.2f / %.2f (+ bias %.2f)", fp.lambda, uv.w, p_.lodBias)});
    counters.push_back(
        {"probe anisotropic", fmt("N = %.0f probes at lambda' = %.2f", fp.probes, fp.lambdaAniso + p_.lodBias)});
  }

  // Samples every covered pixel's footprint (read back from the scene pass) on the CPU: the
  // reference sampler, or with impl=student the LOD and trilinear filter of exercises.cpp.
  void cpuReference() {
    const sampling::SamplerState s = samplerState();
    const glm::ivec2 size(chain_[0].width, chain_[0].height);
    FootprintReference::Sampler sampler = [&](glm::vec2 uv, glm::vec2 dx, glm::vec2 dy) {
      if (p_.impl == Impl::Student)
        return ex06::sampleTrilinear(chain_, uv, ex06::lodFromDerivatives(dx, dy, size) + s.lodBias);
      return sampling::sample(chain_, uv, dx, dy, s);
    };
    const bool volume = p_.texture == TexChoice::Volume;
    const auto r = cpuView_.sample(target_, volume ? nullptr : sampler, p_.view == View::Difference, p_.diffGain);
    counters.push_back({"CPU vs GPU RMSE", volume ? std::string("n/a (3D texture)")
                                                  : fmt("%.2f of 255 over %.0f pixels", r.rmse, double(r.pixels))});
  }

  // The same frame at supersample^2 the pixels with the best filter (trilinear, 16x), box-filtered
  // down: RMSE against it, and the frame-to-frame change (flicker) of both, printed per frame.
  void measure(const FrameInfo& f) {
    sampling::SamplerState best = samplerState();
    best.mag = best.min = Filter::Linear;
    best.mip = MipFilter::Linear;
    best.maxAniso = 16;
    best.lodBias = 0;
    const auto r = supersampled_.measure(target_, p_.supersample, [&](const gl::FootprintTarget& t) {
      gl::applySamplerState(sampler_.id(), best);
      drawScene(t, best, f.width, f.height);
      gl::applySamplerState(sampler_.id(), samplerState());
    });
    std::printf("measure frame=%d rmse=%.4f flicker=%.4f ref_flicker=%.4f\n", f.index, r.rmse, r.flicker,
                r.referenceFlicker);
    std::fflush(stdout);
    counters.push_back({"RMSE vs supersampled",
                        fmt("%.2f of 255 (%.0fx%.0f reference)", r.rmse, r.referenceWidth, r.referenceHeight)});
  }

  Params p_;
  ExerciseProgram program_{"06 scene", {"06_texture_filtering/scene.vert", "06_texture_filtering/scene.frag"}, [this] {
                             return p_.impl == Impl::Student;
                           }};  // GLSL exercises 06.8, 06.9
  gl::Sampler sampler_;
  gl::GpuMesh ground_, tunnel_, sphere_;
  gl::Texture texture_, normalMap_, rip_, volume_;
  gl::FootprintTarget target_;
  FootprintReference cpuView_;
  SupersampledError supersampled_;
  std::vector<ImageF> chain_;
  std::vector<int> ripOffsetX_, ripOffsetY_;
  TexChoice builtTexture_ = TexChoice::CheckerFine;
  int builtVolume_ = -1;
};

int main(int argc, char** argv) { return runLesson<TextureFilteringLesson>(argc, argv); }

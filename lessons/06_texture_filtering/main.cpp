// Lesson 06: texture filtering, from texels to anisotropy ([Tarantsev-L12], textures). A ground plane to
// the horizon, a tunnel and a sphere, textured with patterns that alias; every filter of the
// lecture on a GL sampler object: wrap modes, nearest/linear magnification, the four mipmap modes,
// trilinear, anisotropic 1x-16x, LOD bias; RIP maps filtered in the shader; texture coordinates
// explicit or projected (planar, cylindrical, spherical); replace/modulate/blend per channel;
// normal maps under a moving light; a slice of a 3D texture. Under the cursor (probe.x/probe.y
// headless): the footprint, lambda and the anisotropic probes, from the CPU and from the shader.
// A CPU reference sampler (algorithms/texture_sampling) renders the same footprints for a difference view.
//
// Controls: left drag orbit, right drag pan, wheel zoom; each hotkey is declared with its parameter
// below (F1, --list-hotkeys and the README's Controls list them); F1 help.
// Exercises (exercises.hpp): mip count and memory, LOD, bilinear, trilinear, anisotropic probes,
// box downsample. `--set impl=student --set view=cpu_reference` samples with your code.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "app/exercise_program.hpp"
#include "app/filter_textures.hpp"
#include "app/filtering_readout.hpp"
#include "app/lesson.hpp"
#include "exercises.hpp"
#include "gl/caps.hpp"
#include "scenes.hpp"

using namespace shadowlab;
using namespace lesson06;
using sampling::Filter;
using sampling::MipFilter;
using sampling::Wrap;

namespace {

enum class TexChoice { CheckerFine, Checker, Text, Bricks, ZonePlate, Volume };
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

const char* const kTextures[] = {"checker_fine", "checker", "text", "bricks", "zone_plate", "volume"};
constexpr int kVolumeSizes[] = {32, 64, 128, 256};

// What the launcher and the F1 overlay say about this lesson.
const char* const kSummary =
    "Texels and pixels: wrap modes, magnification, the four mipmap modes, trilinear, anisotropic, RIP "
    "maps, normal maps.";
const char* const kHelp = R"(Look at the ground plane near the horizon: that is minification.
Try: filter.mip=none with filter.min=nearest (moire), then trilinear, then filter.aniso=16;
view=mip_level colours the level per pixel; the header shows lambda and the anisotropic
probes under the cursor; view=difference compares the GPU with the CPU reference sampler.)";

}  // namespace

class TextureFilteringLesson : public Lesson {
 public:
  void declare(ParamRegistry& r) override {
    camera.aim({0, 1, 0}, 4.0f, 0.12f);  // low over the ground plane: every LOD to the horizon
    camera.farZ = 500.0f;
    r.addChoice("scene", &p_.scene, {"ground", "tunnel", "sphere"}, "a plane to the horizon, a tunnel, a sphere")
        .hotkey = "G";
    r.addChoice("texture", &p_.texture, {std::begin(kTextures), std::end(kTextures)},
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
    exercises.addGlsl("06.8", "ripLevelOfDetail", "sampling=rip_map reads level 0 everywhere: aliasing",
                      "sampling=rip_map");
    exercises.addGlsl("06.9", "ripBilinear", "sampling=rip_map is black wherever the texture is", "sampling=rip_map");
    r.add("diff_gain", &p_.diffGain, 1.0f, 64.0f, "difference view: |GPU - CPU| times this");
  }

  LessonInfo info() const override {
    return {"06",
            "06_texture_filtering",
            "Texture filtering",
            kSummary,
            2,
            kHelp,
            false,
            90,
            {"01"},
            {"probe lambda CPU / GPU", "probe anisotropic", "CPU vs GPU RMSE"}};
  }

  void init() override {
    program_.build();
    sampler_ = gl::makeSampler("06 filter sampler");
    shapes_ = makeShapes();
    textures_.loadNormalMap("bricks normal map");
    loadTexture();
  }

  void resize(int w, int h) override {
    target_ = gl::makeFootprintTarget(w, h, true, "06 scene target");
    cpuView_.resize(w, h);
    supersampled_.reset();
  }

  void update(const FrameInfo& f) override {
    loadTexture();  // when texture or volume.size changed
    if (p_.animateLight) p_.lightAngle = std::remainder(p_.lightAngle + 0.6f * float(f.dt), 6.2831853f);
    if (p_.path) camera.target.x += p_.pathSpeed * float(f.dt);
  }

  void render(const FrameInfo& f) override {
    const float aniso = gl::applySamplerState(sampler_.id(), samplerState());
    // ==== 1. the scene: texture coordinates, filtering, combination =================================
    {
      auto t = scope("scene");
      drawScene(target_, samplerState(), f.width, f.height);
      if (p_.view == View::MipLevel) legends.push_back(mipLevelLegend());
      if (p_.view == View::Anisotropy) legends.push_back(anisotropyLegend());
    }
    // ==== 2. readout under the cursor: footprint, lambda, anisotropic probes =========================
    {
      auto t = scope("probe readout");
      probeReadout(f, aniso);
    }
    // ==== 3. CPU reference sampler and the difference view ==========================================
    if (cpuView()) {
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
      glBindFramebuffer(GL_READ_FRAMEBUFFER, cpuView() ? cpuView_.framebuffer() : target_.fbo.id());
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f.framebuffer);
      glBlitFramebuffer(0, 0, f.width, f.height, 0, 0, f.width, f.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      markPixel(f.framebuffer, probePixel(p_.probeX, p_.probeY, f.width, f.height));
    }
  }

  void gui() override { followMouse(p_.probeX, p_.probeY); }

 private:
  // What the lesson's sampler object holds (gl::applySamplerState) and the CPU sampler mirrors: mag,
  // min, mip, wrap s and t, border, LOD bias, max anisotropy.
  sampling::SamplerState samplerState() const {
    return {p_.mag, p_.min, p_.mip, p_.wrapS, p_.wrapT, glm::vec4(p_.border, 1), p_.lodBias, float(p_.aniso)};
  }
  bool cpuView() const { return p_.view == View::CpuReference || p_.view == View::Difference; }

  // scene.frag's modes: constants of a specialised build, or the uniforms of its generic one.
  std::vector<gl::ShaderMode> shaderModes() const {
    return {{"UV_MODE", "uUvMode", int(uvMode(p_.uv, p_.scene)) - 1},
            {"VIEW", "uView", cpuView() ? 3 : std::min(int(p_.view), 2)},
            {"SAMPLING", "uSampling", p_.texture == TexChoice::Volume ? 2 : int(p_.sampling)},
            {"COMBINE", "uCombine", int(p_.combine)},
            {"CHANNELS", "uChannels", int(p_.channels)},
            {"NORMAL_MAPPING", "uNormalMapping", int(p_.normalMap)}};
  }

  void loadTexture() { textures_.update(kTextures[int(p_.texture)], kVolumeSizes[p_.volumeSize], "06"); }

  void drawScene(const gl::FootprintTarget& t, const sampling::SamplerState& s, int w, int h) {
    const glm::vec3 sky(0.55f, 0.7f, 0.9f);
    gl::clearFootprintTarget(t, sky);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const glm::mat4 viewProj = camera.projection(float(w) / float(h)) * camera.view();
    const std::vector<gl::ShaderMode> modes = shaderModes();
    gl::Program& program = program_.get(gl::modeDefines(modes));
    program.use();
    gl::setModeUniforms(program, modes);
    program.set("uViewProj", viewProj);
    program.set("uEye", camera.position());
    program.set("uUvScale", uvTiling(uvMode(p_.uv, p_.scene), p_.scene) * p_.uvScale);
    program.set("uEnvColor", p_.envColor);
    program.set("uMaterial", glm::vec3(0.9f, 0.88f, 0.85f));
    program.set("uSky", sky);
    program.set("uLightPos",
                camera.target + glm::vec3(3.0f * std::cos(p_.lightAngle), 1.0f, 3.0f * std::sin(p_.lightAngle)));
    program.set("uLodBias", s.lodBias);
    // Without GL_CLAMP_TO_BORDER (WebGL2) the shader paints the border colour where a clamp_to_border axis leaves
    // [0,1].
    program.set("uWrapBorder",
                glm::vec2(s.wrapS == sampling::Wrap::ClampToBorder, s.wrapT == sampling::Wrap::ClampToBorder));
    program.set("uBorderColor", s.border);
    program.set("uMaxAniso", float(gl::caps().anisotropic ? std::min(s.maxAniso, gl::caps().maxAnisotropy) : 1.0f));
    program.set("uSlice", p_.slice);
    const gl::FilterTexture& tex = textures_.texture;
    gl::setRipUniforms(program, tex);
    const GLuint units[4] = {tex.mips.id(), textures_.normalMap.id(), tex.rip.id(), textures_.volume.id()};
    const GLenum targets[4] = {GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_3D};
    const char* names[4] = {"uTex", "uNormalMap", "uRip", "uVolume"};
    for (int i = 0; i < 4; ++i) {
      glActiveTexture(GLenum(GL_TEXTURE0 + i));
      glBindTexture(targets[i], units[i]);
      glBindSampler(GLuint(i), i == 2 ? 0 : sampler_.id());  // the lesson's sampler object holds every mode
      program.set(names[i], i);
    }
    const Shape& shape = shapes_[int(p_.scene)];
    program.set("uModel", shape.model);
    program.set("uNormalMatrix", glm::inverseTranspose(glm::mat3(shape.model)));
    shape.mesh.draw();
    for (int i = 3; i >= 0; --i) {
      glActiveTexture(GLenum(GL_TEXTURE0 + i));
      glBindSampler(GLuint(i), 0);
    }
  }

  // The pixel under the cursor: its footprint computed on the CPU beside the hardware's lambda.
  void probeReadout(const FrameInfo& f, float aniso) {
    const glm::ivec2 size = textures_.texture.size();
    const FootprintSample probe = readFootprint(target_, probePixel(p_.probeX, p_.probeY, f.width, f.height));
    const sampling::Footprint fp = sampling::footprint(probe.dx, probe.dy, size, aniso);
    counters = textureMemoryCounters(size, int(textures_.texture.chain.size()), kVolumeSizes[p_.volumeSize], aniso);
    appendProbeCounters(counters, {p_.probeX, p_.probeY}, probe, fp, size, p_.lodBias);
  }

  // Samples every covered pixel's footprint (read back from the scene pass) on the CPU: the
  // reference sampler, or with impl=student the LOD and trilinear filter of exercises.cpp.
  void cpuReference() {
    const sampling::SamplerState s = samplerState();
    const std::vector<ImageF>& chain = textures_.texture.chain;
    FootprintReference::Sampler sampler = [&](glm::vec2 uv, glm::vec2 dx, glm::vec2 dy) {
      if (p_.impl == Impl::Student)
        return ex06::sampleTrilinear(chain, uv, ex06::lodFromDerivatives(dx, dy, textures_.texture.size()) + s.lodBias);
      return sampling::sample(chain, uv, dx, dy, s);
    };
    const bool volume = p_.texture == TexChoice::Volume;
    // The reference's rows on every core (the GPU's work is done by now); a student's sampler on one
    // thread: exercise code need not be safe to call from several at once.
    const auto r = cpuView_.sample(target_, volume ? nullptr : sampler, p_.view == View::Difference, p_.diffGain,
                                   p_.impl == Impl::Student ? 1 : 0);
    counters.push_back(volume ? Counter{"CPU vs GPU RMSE", "n/a (3D texture)"} : referenceCounter(r));
  }

  // The same frame at supersample^2 the pixels with the best filter (trilinear, 16x), box-filtered
  // down: RMSE against it, and the frame-to-frame change (flicker) of both, printed per frame.
  void measure(const FrameInfo& f) {
    const sampling::SamplerState best = sampling::bestFilter(samplerState());
    const auto r = supersampled_.measure(target_, p_.supersample, [&](const gl::FootprintTarget& t) {
      gl::applySamplerState(sampler_.id(), best);
      drawScene(t, best, f.width, f.height);
      gl::applySamplerState(sampler_.id(), samplerState());
    });
    printMeasureLine(f.index, r);
    counters.push_back(supersampledCounter(r));
  }

  Params p_;
  ExerciseProgram program_{"06 scene", {"06_texture_filtering/scene.vert", "06_texture_filtering/scene.frag"}, [this] {
                             return p_.impl == Impl::Student;
                           }};   // GLSL exercises 06.8, 06.9
  gl::Sampler sampler_;          // one sampler object: every filter mode of the lesson
  std::array<Shape, 3> shapes_;  // per SceneKind
  FilterTextures textures_;      // the chosen one (mip chain on both sides, RIP atlas), the 3D one, the normal map
  gl::FootprintTarget target_;
  FootprintReference cpuView_;
  SupersampledError supersampled_;
};

int main(int argc, char** argv) { return runLesson<TextureFilteringLesson>(argc, argv); }

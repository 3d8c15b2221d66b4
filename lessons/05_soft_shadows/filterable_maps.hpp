#pragma once
// Filterable shadow maps (lesson 05), what users of real engines ask about: maps whose texels may
// be averaged, so one blur per frame (instead of many taps per pixel) gives every shadow the same
// soft edge, in five kinds (one class, five techniques; their maths in algorithms/moment_maps):
//   vsm    variance shadow maps (Donnelly and Lauritzen 2006): moments (t, t^2) and Chebyshev's
//          bound; where casters overlap in the kernel the variance is large and light BLEEDS into
//          the shadow (uBleed trims it)
//   esm    exponential shadow maps (Annen et al. 2008): exp(c t) and exp(c (t_occ - t))
//   evsm2  exponential variance shadow maps (Lauritzen and McCool 2008): VSM of exp(c+ t'),
//   evsm4  and of -exp(-c- t') too (t' = 2 t - 1): a far receiver's bound much tighter
//   msm    moment shadow maps (Peters and Klein 2015): (t, t^2, t^3, t^4) and the Hamburger bound,
//          in 32-bit floats or their optimised 16-bit form (the same 8 bytes a texel as VSM)
// The light camera is the sphere's centre camera (SoftMaps, without its depth maps; a point light
// inside the scene: a cube's six faces, drawn as the tiles of a 3 x 2 atlas, blurred together:
// a face's tile is wider than what it is looked up for, so the blur across a tile's edge lands
// where no lookup reads); the depth pass
// is CasterPass with shaders/05_soft_shadows/depth_moments.frag, the blur shaders/05_soft_shadows/blur.frag.
// GLSL: shaders/05_soft_shadows/shadow_filterable.frag.
#include <array>

#include "technique/pass_key.hpp"
#include "soft_maps.hpp"

namespace shadowlab::tech {

enum class MomentFormat { Float32, Unorm16 };  // msm.format: 32f, 16

struct FilterableParams {
  int blur = 2;                // Gaussian radius in texels (sigma = radius / 2): the one penumbra width
  float minVariance = 2e-6f;   // vsm: variance floor (depth precision)
  float bleed = 0.2f;          // vsm: light-bleeding reduction, the share of Chebyshev's tail cut away
  float exponent = 60.0f;      // esm: c (exp(c) must stay finite in 32-bit floats: c <= 88)
  float evsmPositive = 40.0f;  // evsm: c+ (its square must stay finite: c+ <= 42, soft::kEvsmMaxExponent)
  float evsmNegative = 5.0f;   // evsm4: c-
  MomentFormat msmFormat = MomentFormat::Unorm16;  // msm: the optimised 16-bit form (or floats, twice the memory)
  float momentBias = 3e-5f;  // msm: alpha, the moments pulled toward 0.5 (the paper's for 16 bits)
  bool reuseMaps = true;     // keep a light's moments while nothing they depend on changed (PassKey)
  // 1024^2 and a 2-texel blur: on the showcase both blurred less and sampled finer measured closer
  // to the reference than 512^2 and 4 texels (tools/soft_bench.sh), and the contact stays dark.
  SoftMapParams maps{.mapSize = 1024};
};

class FilterableMaps : public ShadowTechnique {
 public:
  enum class Kind { Vsm, Esm, Evsm2, Evsm4, Msm };
  explicit FilterableMaps(Kind kind, FilterableParams defaults = {});
  std::string name() const override;
  void declare(ParamRegistry& r, const std::string& prefix) override;
  void init() override;
  void pushShapes(const ShadowContext& c) const override { maps_.pushShapes(c); }
  const ShadowStats& stats() const override { return stats_; }
  std::string visibilityShader() const override { return "05_soft_shadows/shadow_filterable.frag"; }
  std::vector<std::string> shaderDefines() const override;
  void bindVisibility(const gl::Program& lit, int firstUnit) const override;
  void unbindVisibility(int firstUnit) const override;
  FilterableParams& params() { return p_; }

 private:
  void render(const ShadowContext& c) override;
  struct Target {
    gl::Texture moments, scratch;  // the blur ping-pongs between them
    gl::Renderbuffer depth;
    gl::Framebuffer fbo, scratchFbo;
    int size = 0;
    int faces = 1;  // 6: a cube's faces in a 3 x 2 atlas
    GLenum format = 0;
    PassKey rendered;    // what the moments were last drawn and blurred from
    DrawnFigures drawn;  // what that cost (kept moments' figures)
  };
  void ensure(Target& t, int size, int faces, const std::string& label);
  static glm::ivec2 atlasExtent(int size, int faces);
  std::string cubeRefusal(int size) const;  // why a cube's atlas cannot be had ("" where it can)
  bool msm16() const { return kind_ == Kind::Msm && p_.msmFormat == MomentFormat::Unorm16; }
  GLenum textureFormat() const;
  static GLenum storedFormat(GLenum format);
  std::string formatNote() const;  // "" where the moments are stored as textureFormat() says
  bool halfFloats() const;         // stored in 16-bit floats (the fallback): smaller exponents
  float esmExponent() const;
  glm::vec2 evsmExponents() const;  // (c+, c-), as the format holds them
  int bytesPerTexel() const;
  glm::vec4 farMoments() const;  // what a texel holds where nothing is in front (t = 1)
  void blur(Target& t);

  Kind kind_;
  FilterableParams p_;
  SoftMaps maps_;
  CasterPass casters_;
  gl::Program blur_{"filterable maps: blur", {"common/fullscreen.vert", "05_soft_shadows/blur.frag"}};
  gl::VertexArray vao_;
  std::array<Target, kMaxLights> targets_;  // per light
  gl::Texture dummy_;                       // 1^2 "nothing in front": bound where a light has no map
  ShadowStats stats_;
};

}  // namespace shadowlab::tech

#pragma once
// The shadow maps of the techniques that warp space before rendering depth (perspective shadow
// maps, LiSPSM): per light up to six square depth maps of one size, the layers of one 2D array
// texture, each rendered with its own world -> map clip matrix. The matrices are projective and are
// applied to homogeneous world points, never divided first: a caster behind the camera has clip
// w < 0 after the camera's projection, and only the product with the light's (negative) w makes
// it visible to the rasteriser (Kozlov et al., "Perspective Shadow Maps: Care and Feeding", §3).
// The shared controls: the TOTAL texels of a light (a face set splits them), the depth format,
// the filter, and the bias: a constant in depth, or the paper's world-space texel-size bias (§5,
// fix 4) applied to every caster vertex in the depth pass (shaders/08_psm/depth_psm.vert).
// shaders/08_psm/shadow_psm.frag reads them.
#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/psm/psm_plan.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"
#include "gl/shadow_map.hpp"
#include "technique/pass_key.hpp"
#include "technique/casters.hpp"
#include "technique/technique.hpp"

namespace shadowlab::tech {

inline constexpr int kPsmLights = 2;  // PSM_LIGHTS in shaders/08_psm/shadow_psm.frag
inline constexpr int kPsmMaps = 6;    // PSM_MAPS: a face set has at most six

enum class ProjectiveBias { Constant, WorldTexel };
enum class ProjectiveFilter { Nearest, Hardware2x2 };

struct ProjectiveMapParams {
  int mapSize = 2048;                                       // texels per side of a light's TOTAL (kMapSizes)
  gl::DepthFormat format = gl::DepthFormat::Depth24;        // the paper: 24 bits suffice for the inverse projection
  ProjectiveFilter filter = ProjectiveFilter::Hardware2x2;  // GL_LINEAR compare: hardware 2x2 PCF
  ProjectiveBias bias = ProjectiveBias::WorldTexel;         // fix 4; Constant is what it replaces
  float constantBias = 0.0005f;                             // window-depth units subtracted before the comparison
  float worldA = 0.02f;                                     // a: world units every caster moves away from the light
  float worldB = 1.5f;                                      // b: times the world size of one texel there
  float worldMax = 1.0f;                                    // the most a caster moves (a texel can be unbounded)
  float slopeOffset = 1.0f;   // glPolygonOffset factor: steep casters in the map's own depth
  float normalOffset = 1.0f;  // the lookup moves this many texels (their world size there) along N, times sin(theta)
  // The receiver plane (Isidoro 2006): each of the lookup's taps compares against the receiver's
  // own plane at that texel's centre, its depth slope from the world point's screen derivatives
  // through the map's projective matrix. Then planeNormalOffset applies where the pixel's facet
  // faces the light, none at a smooth surface's terminator (facet away, normal towards the light)
  // and normalOffset only where the normal faces away (V unseen). Off by default: see lesson 09's
  // README ("The receiver plane") for what it gains and what it costs.
  bool receiverPlane = false;
  float planeNormalOffset = 0.0f;
  bool reuseMaps = true;  // skip a light's depth passes when nothing they depend on changed (PassKey)
};

// One map to render: its world -> clip matrix (double, converted at the GL boundary), and the
// casters it draws when it culls its own (cascades: keep[i] for scene object i; empty: the light's).
struct ProjectiveMapView {
  glm::dmat4 worldToClip{1.0};
  std::span<const char> keep;
};

// What the lit shader needs to pick a light's face map (fix 3): the camera whose post-projective
// space the faces belong to, the light there, and which layer holds each hidden face.
struct FaceLookup {
  bool faces = false;
  glm::dmat4 cameraViewProj{1.0};
  glm::dvec4 postLight{0.0};         // (position, 1) or (direction, 0)
  std::array<int, 6> layerOfFace{};  // -1: no map on that face
};

// The rough receiver volumes of the scene (psm::receiverVolumes), rebuilt only when the scene or
// the tile count changes.
class ReceiverVolumes {
 public:
  std::span<const Aabb> get(const SceneCache& scene, int tiles);

 private:
  std::vector<Aabb> boxes_;
  std::uint64_t revision_ = 0;
  int tiles_ = -1;
};

// keep[i]: scene object i may shade the view frustum for the light (psm::potentialCasters), or
// every caster when `cull` is off. Returns how many casters were left out.
int selectCasters(const SceneCache& scene, const psm::Frustum& view, const glm::dvec4& light, bool cull,
                  std::vector<char>& keep);

class ProjectiveMapSet {
 public:
  explicit ProjectiveMapSet(ProjectiveMapParams defaults) : p_(defaults) {}
  void declare(ParamRegistry& r, const std::string& prefix);
  void init();
  ProjectiveMapParams& params() { return p_; }
  const ProjectiveMapParams& params() const { return p_; }
  int totalSide() const;  // the side whose square is a light's texel budget

  // Light i's maps for this frame: `maps.size()` layers of side x side texels, drawing the scene's
  // casters where keep[i] (empty: every caster), or where the map's own keep says. worldLight: (position, 1) or
  // (-direction, 0), the direction casters move in for the world-space bias. Counts into stats.
  void render(const ShadowContext& c, int light, std::span<const ProjectiveMapView> maps, int side,
              std::span<const char> keep, const glm::dvec4& worldLight, const FaceLookup& faces, ShadowStats& stats);
  void disable(int light);  // light i has no map this frame: V = 1
  void bind(const gl::Program& lit, int firstUnit) const;
  void unbind(int firstUnit) const;
  bool anyFaces() const;
  // The lit program's variant for these maps: PSM_FACES (some light has face maps), PSM_NORMAL_OFFSET.
  std::vector<std::string> shaderDefines() const;
  // One map's casters drawn moved by a student's world-space bias (exercise 09.4, evaluated per
  // caster vertex on the CPU: lesson 09's CpuBiasPass), into the map's bound framebuffer. Returns
  // the triangles drawn.
  struct BiasedDraw {
    const ShadowContext& c;
    const glm::dmat4& worldToClip;
    int side;                      // the map's texels per side
    std::span<const char> keep;    // the casters to draw (empty: every one)
    const glm::dvec4& worldLight;  // (position, 1) or (-direction, 0)
    double a, b;                   // bias.a, bias.b
    const CasterOptions& options;  // both faces, alpha-tested, as the reference's pass
    float slopeOffset;             // glPolygonOffset's factor (depth_psm.frag without GL_DEPTH_CLAMP)
  };
  using WorldBias = std::function<std::size_t(const BiasedDraw&)>;
  // The steps of lessons 08 and 09 that the maps run (impl=student, set by the PSM technique);
  // empty or false: the reference (the bias in the depth pass's vertex shader).
  struct Student {
    WorldBias worldBias;      // 09.4: lesson 09 draws the casters its texelSizeBias moved
    bool glslLookup = false;  // 08.3, psmMapCoords: shaderDefines() add SHADOWLAB_STUDENT_PSM_LOOKUP
    bool glslFaces = false;   // 09.6, cubeFaceLayer: shaderDefines() add SHADOWLAB_STUDENT_PSM_FACES
  };
  Student student;
  // The layers of light i side by side in (x, y, w, h) of the bound framebuffer (view=map).
  void drawLayers(int light, int x, int y, int w, int h);

 private:
  struct PerLight {
    gl::Texture array;
    gl::Framebuffer fbo;
    int side = 0, layers = 0, used = 0;
    gl::DepthFormat format = gl::DepthFormat::Depth24;
    std::array<glm::mat4, kPsmMaps> matrices{};
    std::array<glm::vec4, kPsmMaps> texelStep{}, clipW{};  // fix 4's factors, for the receiver's texel size
    FaceLookup faces;
    int generation = 0;  // counts the array's re-creations: a new array holds no map yet
    PassKey rendered;    // what the maps were last drawn from
    DrawnFigures drawn;  // what they cost then (kept maps' figures)
  };
  PassKey passKey(const ShadowContext& c, const PerLight& l, std::span<const ProjectiveMapView> maps, int side,
                  std::span<const char> keep, const glm::dvec4& worldLight) const;
  void ensureArray(PerLight& l, int light, int side, int layers);
  void setBiasUniforms(const glm::dmat4& worldToClip, int side, const glm::dvec4& worldLight);

  ProjectiveMapParams p_;
  std::array<PerLight, kPsmLights> lights_;
  CasterPass casters_{"projective maps: depth pass", "08_psm/depth_psm.vert", "uLightViewProj",
                      "08_psm/depth_psm.frag"};
  gl::Sampler compareNearest_, compareLinear_, raw_;
  gl::Texture dummy_;
  gl::Program layersView_{"projective maps: layers", {"common/fullscreen.vert", "08_psm/depth_layers.frag"}};
  gl::VertexArray emptyVao_;
};

}  // namespace shadowlab::tech

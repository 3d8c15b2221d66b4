#pragma once
// The depth pass every shadow-map technique runs once per light camera: the casters that camera
// keeps, drawn with the course's one depth program (shaders/common/depth.vert and .frag), so an
// alpha-tested card discards its holes here too and casts the shadow of its leaves, not of a
// solid card (Boreskov's tutorial, docs/references.md). The caller binds the map's framebuffer
// (gl::beginShadowPass) and sets the polygon offset; the GL calls of the pass are here.
//
// The fragment shader is built three ways (shaders/common/caster_alpha.glsl): for opaque casters
// (no texture fetch, no discard), and for alpha-tested ones at the footprint's mip level or at level
// 0. Each caster is drawn with the build it needs: on llvmpipe a depth shader that only might
// discard made lesson 03's city (every caster opaque) pay a texture fetch per fragment and its
// early depth test; with the opaque build its frame went from about 170 to about 105 ms.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "gl/program.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {

struct CasterOptions {
  bool alphaTest = true;    // discard alpha-tested texels (off: solid cards, the lesson-02 mistake)
  bool cullFront = false;   // draw back faces only: a closed caster's own thickness is the bias
  bool allObjects = false;  // every object, casting or not (a depth pre-pass from the eye)
  // Cull at all. Off for maps rendered after the camera's projection (perspective shadow maps):
  // a caster behind the camera comes out mirrored (its w changes sign twice), so its front faces
  // would be culled; and a one-sided wall seen from behind must still cast.
  bool cull = true;
  // Vertices computed on the CPU (a student's per-vertex bias): a vertex array with WORLD positions
  // for object i (the mesh's indices and uvs), or 0 for the mesh's own; empty: every mesh's own.
  std::function<GLuint(std::size_t object)> worldVertexArray;
  // Test the alpha of the texture's level 0, as the ground truth's rays do (common/measure), not of
  // the mip level a map texel's footprint picks: a coarse level's averaged alpha against the cutoff
  // closes the cards' small holes and thins their leaves, the same way in every map of a light.
  // Every light's map does; the eye's depth pre-pass does not (what the eye sees of a card is the
  // lit pass's mip level, antialiased like any texture).
  bool alphaLevel0 = true;
  // The objects in this order (empty: the scene's): a pre-pass draws near to far, so the depth
  // test rejects hidden fragments before their alpha fetch.
  std::span<const std::uint32_t> order;
  // And within a mesh with view orders (gl::GpuMesh), its triangles nearest the viewer first: the
  // eye or light position (w = 1), or the direction toward the viewer (w = 0). Empty: where the
  // pass's own projection looks from (viewerOf), but for a map after the camera's projection
  // (cull off: the perspective shadow maps), which keeps each mesh's own order.
  std::optional<glm::vec4> viewer;
};

class CasterPass {
 public:
  // `vertexShader` and its view-projection uniform: the light's depth pass (a technique may move
  // its casters there, e.g. the world-space bias of perspective shadow maps, 08_psm/depth_psm.vert),
  // or (common/scene.vert, uViewProj) for a pre-pass whose depth a lit pass with the same vertex
  // shader tests EQUAL against. `fragmentShader`: a filterable map (VSM, ESM) writes its moments
  // from one of its own, with the same alpha test.
  explicit CasterPass(std::string label = "depth pass", std::string vertexShader = "common/depth.vert",
                      std::string viewProjUniform = "uLightViewProj", std::string fragmentShader = "common/depth.frag");
  void build();
  // Sets the uniforms a shader of the caller's own reads (a technique's depth pass, a filterable
  // map's fragment shader) in every build of the program: `set` is called with each, in use.
  void setUniforms(const std::function<void(const gl::Program&)>& set) const;
  // Draws object i when keep[i] (an empty span: every object that casts). Returns the triangles drawn.
  std::size_t draw(const SceneCache& scene, const glm::mat4& viewProj, std::span<const char> keep,
                   const CasterOptions& options);

 private:
  enum Build { Opaque, AlphaMip, AlphaLevel0, BuildCount };
  // Opaque, AlphaMip, AlphaLevel0: each a Program (registered by address, so held by pointer).
  std::array<std::unique_ptr<gl::Program>, BuildCount> programs_;
  std::string viewProjUniform_;
};

}  // namespace shadowlab::tech

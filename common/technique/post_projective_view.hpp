#pragma once
// The post-projective view: the scene drawn AFTER the camera's projection, the picture perspective
// shadow maps are about. The view frustum is the unit cube [-1,1]^3 there; near things are big and
// far things crowd the far face; the eye is at infinity (view rays are parallel to z); a
// directional light lands on the plane just behind the far face, or stays a direction when it is
// parallel to the near plane; a light behind the camera lands there too, but its rays leave it away
// from the cube and come back through infinity (Kozlov et al., "Perspective Shadow Maps: Care and
// Feeding" §3-4). With the technique's own shapes (PostProjectiveSubject::describePostProjective): its
// light frusta (through infinity where they go), the cone, the key points, a slid virtual camera's
// real cube inside it. An inset in the bottom-left corner (the god view has the other), or the whole
// frame. Any lesson holds one for whichever technique it shows.
//
// Points are homogeneous all the way: the scene's vertices become h = P V x (never divided), the
// display camera takes h itself, and the rasteriser divides; each draw runs twice, with h and with
// -h and a clip plane at w = 0, so the parts behind the camera (w < 0) appear beyond the plane at
// infinity where projective geometry puts them (view.post_behind).
#include <string>

#include "app/measurement.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"
#include "technique/technique.hpp"

namespace shadowlab::psm {
class PostProjectiveShapes;
}

namespace shadowlab::tech {

// A technique that shows itself in the post-projective view (the uniform maps, PSM, LiSPSM, the
// cascades); any other technique gets the viewer's space and no shapes of its own.
class PostProjectiveSubject {
 public:
  virtual ~PostProjectiveSubject() = default;
  // The camera whose post-projective space shows light `light`: the viewer's (the default), or a
  // perspective shadow map's virtual camera slid back behind it.
  virtual glm::dmat4 postProjectiveCamera(const ShadowContext& c, int light) const {
    return glm::dmat4(c.viewerViewProj());
  }
  // The technique's own shapes in that space: its light frusta, cones, key points.
  virtual void describePostProjective(const ShadowContext& c, int light, psm::PostProjectiveShapes& out) const = 0;
};

class PostProjectiveView {
 public:
  enum class Mode { Off, Inset, Full };
  // Registers prefix ("view.post"), prefix.size, .yaw, .pitch, .distance, .behind, .light.
  void declare(ParamRegistry& r, const std::string& prefix = "view.post");
  void init();
  bool enabled() const { return mode_ != Mode::Off; }
  Mode mode() const { return mode_; }
  // Draws technique t's view of light `light` (-1: the one the view's parameter names) into
  // c.frame's framebuffer, after the lit frame, timed as "post-projective view"; nothing when the
  // view is off or in a god-view frame. In inset mode the inset goes into `insets` (the lesson's
  // Lesson::insets), so the UI keeps clear of it; its colour key (the colours drawn, named) goes
  // into `legends` (Lesson::legends).
  void draw(const ShadowContext& c, const ShadowTechnique& t, std::vector<Inset>& insets, std::vector<Legend>& legends,
            int light = -1);
  // In inset mode, where the inset goes in a frameWidth x frameHeight frame (bottom-left, GL
  // pixels): lessons report it in Lesson::insets so the UI stays clear of it.
  std::optional<Inset> inset(int frameWidth, int frameHeight) const;
  // The first column right of the inset (0 without one): where a lesson's own bottom-row view starts.
  int rightOfInset(int frameWidth, int frameHeight) const {
    const auto i = inset(frameWidth, frameHeight);
    return i ? i->x + i->width + 8 : 0;
  }

 private:
  glm::mat4 displayView() const;
  void drawScene(const ShadowContext& c, const glm::mat4& camera, const glm::mat4& display);
  // Returns the colours it drew, for the legend.
  std::vector<glm::vec4> drawLines(const ShadowContext& c, const ShadowTechnique& t, int light,
                                   const glm::dmat4& camera, const glm::mat4& display);
  void composite(const ShadowContext& c, int x, int y, int w, int h);

  Mode mode_ = Mode::Off;
  float size_ = 0.38f;     // the inset's width, as a fraction of the frame's
  float yaw_ = 1.3f;       // the display camera around the cube (radians; 0 looks along the eye's rays)
  float pitch_ = 0.4f;     // above the cube's equator
  float distance_ = 8.0f;  // from the cube's centre, in half-cube units
  bool behind_ = false;    // also draw what is behind the camera (beyond the plane at infinity)
  int light_ = 0;          // whose light and light camera the view shows
  gl::RenderTarget target_;
  gl::Program scene_{"post-projective view: scene", {"common/post_projective.vert", "common/post_projective.frag"}};
  gl::Program lines_{"post-projective view: lines",
                     {"common/post_lines.vert", "common/lines.geom", "common/lines.frag"},
                     {"CLIP_DISTANCE0"}};
  // Without a geometry shader (WebGL2): each segment as two triangles (common/lines_quad.vert).
  gl::Program linesQuad_{
      "post-projective view: lines", {"common/lines_quad.vert", "common/lines.frag"}, {"CLIP_DISTANCE0"}};
  gl::Program& linesProgram() { return gl::caps().geometryShaders ? lines_ : linesQuad_; }
  gl::Program blit_{"post-projective view: composite", {"common/fullscreen.vert", "common/overlay.frag"}};
  gl::VertexArray linesVao_, emptyVao_;
  gl::Buffer lineVertices_;
};

}  // namespace shadowlab::tech

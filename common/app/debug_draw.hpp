#pragma once
// Shapes a lesson wants to show in the god view (a second camera outside the scene): frusta, cones,
// boxes, lines. Lessons fill `debug` in render() each frame; the framework clears it per frame and
// draws it, with the main camera's frustum, into the god view inset (view.god, hotkey O).
#include <algorithm>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"

namespace shadowlab {

class DebugDraw {
 public:
  struct Line {
    glm::vec3 a, b;
    glm::vec4 color;
  };
  void clear() {
    lines_.clear();
    names_.clear();
  }
  // What a colour means in the god view's legend ("light frustum"); the first name of a colour wins.
  void name(const glm::vec4& color, const std::string& meaning);
  struct Name {
    glm::vec4 color;
    std::string meaning;
  };
  const std::vector<Name>& names() const { return names_; }
  void line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color);
  // The 12 edges of the volume that `viewProj` maps onto the clip cube [-1,1]^3 (a camera's or a
  // light's frustum, or an orthographic box).
  void frustum(const glm::mat4& viewProj, const glm::vec4& color);
  void box(const Aabb& box, const glm::vec4& color);
  // A cone from `apex` along unit `axis` with half-angle `angle` (radians), `length` long.
  void cone(const glm::vec3& apex, const glm::vec3& axis, float angle, float length, const glm::vec4& color);
  void cross(const glm::vec3& p, float size, const glm::vec4& color);
  const std::vector<Line>& lines() const { return lines_; }

 private:
  std::vector<Line> lines_;
  std::vector<Name> names_;
};

// Draws lines into the bound framebuffer with shaders/common/lines.{vert,frag}: the god view's
// shapes, and lessons' overlays drawn over their own frame (lesson 05's predicted penumbra edges).
class LineRenderer {
 public:
  explicit LineRenderer(std::string label)
      : program_(label, {"common/lines.vert", "common/lines.geom", "common/lines.frag"}),
        quadProgram_(label + " (quads)", {"common/lines_quad.vert", "common/lines.frag"}) {}
  // Where there are no geometry shaders (WebGL2; SHADOWLAB_GL_HIDE=GL_ARB_geometry_shader4 here),
  // the quads come from six vertices a segment, expanded on the CPU (lines_quad.vert).
  void build();
  // depthTest: against the bound depth buffer with GL_LEQUAL (left at GL_LESS after); else over everything.
  // widthPx: the lines' width in pixels of the current viewport (quads from lines.geom).
  void draw(const std::vector<DebugDraw::Line>& lines, const glm::mat4& viewProj, bool depthTest, float widthPx);
  // A width that reads on a projector: 2.5 pixels at 720 lines, in proportion above.
  static float projectorWidth(int frameHeight) { return std::max(2.0f, 2.5f * float(frameHeight) / 720.0f); }

 private:
  gl::Program& active();
  gl::Program program_, quadProgram_;
  gl::VertexArray vao_;
  gl::Buffer vertices_;
};

}  // namespace shadowlab

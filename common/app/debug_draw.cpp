#include "app/debug_draw.hpp"

#include <cmath>
#include <cstddef>

#include "gl/caps.hpp"
#include "gl/gl.hpp"

namespace shadowlab {

void DebugDraw::name(const glm::vec4& color, const std::string& meaning) {
  for (const Name& n : names_)
    if (n.color == color || n.meaning == meaning) return;
  names_.push_back({color, meaning});
}

void DebugDraw::line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color) {
  lines_.push_back({a, b, color});
}

void DebugDraw::frustum(const glm::mat4& viewProj, const glm::vec4& color) {
  const glm::mat4 inv = glm::inverse(viewProj);
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p = inv * glm::vec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
    c[i] = glm::vec3(p) / p.w;
  }
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : kEdges) line(c[e[0]], c[e[1]], color);
}

void DebugDraw::box(const Aabb& b, const glm::vec4& color) {
  if (b.empty()) return;
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : kEdges) line(c[e[0]], c[e[1]], color);
}

void DebugDraw::cone(const glm::vec3& apex, const glm::vec3& axis, float angle, float length, const glm::vec4& color) {
  const glm::vec3 w = glm::normalize(axis);
  const glm::vec3 helper = std::abs(w.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(w, helper)), v = glm::cross(w, u);
  const float r = length * std::tan(angle);
  constexpr int kSegments = 24;
  glm::vec3 previous;
  for (int i = 0; i <= kSegments; ++i) {
    const float t = 2.0f * 3.14159265f * float(i) / kSegments;
    const glm::vec3 p = apex + w * length + r * (std::cos(t) * u + std::sin(t) * v);
    if (i > 0) line(previous, p, color);
    if (i % 6 == 0) line(apex, p, color);
    previous = p;
  }
}

void DebugDraw::cross(const glm::vec3& p, float s, const glm::vec4& color) {
  line(p - glm::vec3(s, 0, 0), p + glm::vec3(s, 0, 0), color);
  line(p - glm::vec3(0, s, 0), p + glm::vec3(0, s, 0), color);
  line(p - glm::vec3(0, 0, s), p + glm::vec3(0, 0, s), color);
}

gl::Program& LineRenderer::active() { return gl::caps().geometryShaders ? program_ : quadProgram_; }

void LineRenderer::build() {
  if (!active().valid()) active().build();
}

namespace {
// The vertices of `lines`: two a segment for lines.geom, or six (two triangles: corners 0 1 2 and
// 1 3 2 of its quad) for lines_quad.vert, each with both ends.
struct LineVertex {
  glm::vec3 p;
  glm::vec4 c;
};
struct QuadVertex {
  glm::vec3 start, end;
  glm::vec4 c;
  float corner;
};
template <class V>
void upload(const std::vector<V>& v) {
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(V)), v.data(), GL_STREAM_DRAW);
}
void attribute(GLuint index, int size, std::size_t stride, std::size_t offset) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, GLsizei(stride), reinterpret_cast<void*>(offset));
}
}  // namespace

void LineRenderer::draw(const std::vector<DebugDraw::Line>& lines, const glm::mat4& viewProj, bool depthTest,
                        float widthPx) {
  build();
  gl::Program& program = active();
  if (!vao_) {
    vao_ = gl::makeVertexArray(program.label());
    vertices_ = gl::makeBuffer(GL_ARRAY_BUFFER, program.label());
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  GLsizei count = 0;
  GLenum mode = GL_LINES;
  if (&program == &program_) {
    std::vector<LineVertex> v;
    v.reserve(lines.size() * 2);
    for (const auto& l : lines) v.push_back({l.a, l.color}), v.push_back({l.b, l.color});
    upload(v);
    attribute(0, 3, sizeof(LineVertex), offsetof(LineVertex, p));
    attribute(1, 4, sizeof(LineVertex), offsetof(LineVertex, c));
    count = GLsizei(v.size());
  } else {
    std::vector<QuadVertex> v;
    v.reserve(lines.size() * 6);
    for (const auto& l : lines)
      for (int corner : {0, 1, 2, 1, 3, 2}) v.push_back({l.a, l.b, l.color, float(corner)});
    upload(v);
    attribute(0, 3, sizeof(QuadVertex), offsetof(QuadVertex, start));
    attribute(1, 3, sizeof(QuadVertex), offsetof(QuadVertex, end));
    attribute(2, 4, sizeof(QuadVertex), offsetof(QuadVertex, c));
    attribute(3, 1, sizeof(QuadVertex), offsetof(QuadVertex, corner));
    count = GLsizei(v.size());
    mode = GL_TRIANGLES;
  }
  if (depthTest) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  program.use();
  program.set("uViewProj", viewProj);
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  program.set("uViewport", glm::vec2(float(viewport[2]), float(viewport[3])));
  program.set("uWidth", widthPx);
  glDrawArrays(mode, 0, count);
  gl::countDraws();
  glDepthFunc(GL_LESS);
  if (!depthTest) glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab

#include "app/debug_draw.hpp"

#include <cmath>

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

void LineRenderer::draw(const std::vector<DebugDraw::Line>& lines, const glm::mat4& viewProj, bool depthTest,
                        float widthPx) {
  build();
  struct V {
    glm::vec3 p;
    glm::vec4 c;
  };
  std::vector<V> v;
  v.reserve(lines.size() * 2);
  for (const auto& l : lines) {
    v.push_back({l.a, l.color});
    v.push_back({l.b, l.color});
  }
  if (!vao_) {
    vao_ = gl::makeVertexArray(program_.label());
    vertices_ = gl::makeBuffer(GL_ARRAY_BUFFER, program_.label());
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(V)), v.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(V), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(V), reinterpret_cast<void*>(sizeof(glm::vec3)));
  if (depthTest) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  program_.use();
  program_.set("uViewProj", viewProj);
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  program_.set("uViewport", glm::vec2(float(viewport[2]), float(viewport[3])));
  program_.set("uWidth", widthPx);
  glDrawArrays(GL_LINES, 0, GLsizei(v.size()));
  gl::countDraws();
  glDepthFunc(GL_LESS);
  if (!depthTest) glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab

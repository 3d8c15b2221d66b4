#include "technique/map_view.hpp"

namespace shadowlab::tech {

void DepthMapView::build() {
  program_.build();
  raw_ = gl::makeRawDepthSampler("depth map view");
  vao_ = gl::makeVertexArray("depth map view");
}

void DepthMapView::draw(const gl::ShadowMap& map, int x, int y, int w, int h, std::optional<glm::vec2> nearFar,
                        int unit) {
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glViewport(x, y, w, h);
  glDisable(GL_DEPTH_TEST);
  program_.use();
  program_.set("uDepth", unit);
  program_.set("uPerspective", nearFar.has_value());
  if (nearFar) {
    program_.set("uNear", nearFar->x);
    program_.set("uFar", nearFar->y);
  }
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, map.texture.id());
  glBindSampler(GLuint(unit), raw_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::countDraws();
  glBindSampler(GLuint(unit), 0);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_DEPTH_TEST);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

}  // namespace shadowlab::tech

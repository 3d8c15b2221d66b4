#include "technique/post_projective_view.hpp"

#include "app/debug_draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/psm/post_shapes.hpp"
#include "app/measurement.hpp"
#include "gl/scene_draw.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

const glm::vec4 kCube{0.95f, 0.95f, 0.95f, 1.0f};
const glm::vec4 kInfinity{0.55f, 0.55f, 0.6f, 1.0f};
const glm::vec4 kEyeRays{0.9f, 0.8f, 0.35f, 0.6f};
const psm::PostProjectivePalette kPalette;

// The plane at infinity of a camera's post-projective space: z = (f + n) / (f - n), where every
// direction in front of the camera lands (a directional light, the far ends of view rays).
double planeAtInfinity(const glm::dmat4& viewProj) {
  const glm::dvec3 forward = -glm::dvec3(viewProj[0][3], viewProj[1][3], viewProj[2][3]);  // clip w grows along it
  const glm::dvec4 h = viewProj * glm::dvec4(forward, 0.0);
  return h.z / h.w;
}

// The frame of reference every post-projective view shares: the unit cube, the eye's rays arriving
// parallel from z = -infinity, the plane at infinity, and the light where it lands.
void addFrame(psm::PostProjectiveShapes& s, const glm::dmat4& camera, const glm::dvec4& worldLight) {
  s.unitCube(kCube);
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 corner((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, -1.0);
    s.line(glm::dvec4(0, 0, -1, 0), glm::dvec4(corner, 1.0), kEyeRays);  // from the eye at infinity
  }
  const double q = planeAtInfinity(camera);
  if (std::isfinite(q))
    for (int i = 0; i < 4; ++i) {
      const double a = (i & 1) ? 1.6 : -1.6, b = (i & 2) ? 1.6 : -1.6;
      s.segment({a, -1.6, q}, {a, 1.6, q}, kInfinity);
      s.segment({-1.6, b, q}, {1.6, b, q}, kInfinity);
    }
  const psm::PostProjectiveLight l = psm::toPostProjective(camera, worldLight);
  s.light(l, l.kind == psm::PostLightKind::Behind ? kPalette.lightBehind : kPalette.light);
}

}  // namespace

void PostProjectiveView::declare(ParamRegistry& r, const std::string& n) {
  r.addChoice(n, &mode_, {"off", "inset", "full"},
              "the scene after the camera's projection: the unit cube, the light there, its light camera")
      .hotkey = "P";  // Q flies the camera down (a framework key)
  r.add(n + ".size", &size_, 0.2f, 1.0f, "the inset's width, as a fraction of the frame");
  r.add(n + ".yaw", &yaw_, -3.2f, 3.2f, "the display camera around the cube (0: along the eye's rays)");
  r.add(n + ".pitch", &pitch_, -1.5f, 1.5f, "the display camera above the cube's equator");
  r.add(n + ".distance", &distance_, 1.5f, 60.0f, "the display camera's distance from the cube's centre");
  r.add(n + ".behind", &behind_, "also draw what lies behind the camera: beyond the plane at infinity, tinted red");
  r.add(n + ".light", &light_, 0, 3, "whose light (and light camera) the view shows");
}

void PostProjectiveView::init() {
  scene_.build();
  linesProgram().build();
  blit_.build();
  linesVao_ = gl::makeVertexArray("post-projective view: lines");
  lineVertices_ = gl::makeBuffer(GL_ARRAY_BUFFER, "post-projective view: lines");
  emptyVao_ = gl::makeVertexArray("post-projective view: composite");
}

// Post-projective space is left-handed (z grows away from the eye): the display flips z so that it
// reads like the world, the eye's side toward +z.
glm::mat4 PostProjectiveView::displayView() const {
  const glm::vec3 eye =
      distance_ * glm::vec3(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), std::cos(yaw_) * std::cos(pitch_));
  return glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1));
}

void PostProjectiveView::drawScene(const ShadowContext& c, const glm::mat4& camera, const glm::mat4& view) {
  const float aspect = float(target_.width) / float(target_.height);
  scene_.use();
  scene_.set("uCamera", camera);
  scene_.set("uDisplayView", view);
  scene_.set("uDisplay", glm::perspective(0.7f, aspect, 0.05f, 500.0f) * view);
  scene_.set("uBox", glm::vec2(1.35f, 3.5f));
  gl::SceneDrawOptions options;
  options.textures = false;
  options.beforeDraw = [](std::size_t) { glDisable(GL_CULL_FACE); };  // seen from outside: both sides
  for (const float sign : {1.0f, -1.0f}) {
    if (sign < 0.0f && !behind_) break;
    scene_.set("uSign", sign);
    gl::drawScene(scene_, c.scene.scene(), c.scene.gpu(), options);
  }
  glEnable(GL_CULL_FACE);
}

// What each colour of the view means, in the order the legend lists them.
Legend postProjectiveLegend(const std::vector<glm::vec4>& drawn) {
  const std::pair<glm::vec4, const char*> meanings[] = {{kCube, "unit cube: the view frustum"},
                                                        {kEyeRays, "eye rays, parallel from -infinity"},
                                                        {kInfinity, "the plane at infinity"},
                                                        {kPalette.light, "the light"},
                                                        {kPalette.lightBehind, "the light, behind the camera"},
                                                        {kPalette.realCube, "the real camera's cube"},
                                                        {kPalette.map, "a map's light camera"},
                                                        {kPalette.cone, "the cone over the receivers"},
                                                        {kPalette.keyPoint, "key points"}};
  Legend l{"post-projective view", {}};
  for (const auto& [colour, meaning] : meanings)
    if (std::find(drawn.begin(), drawn.end(), colour) != drawn.end()) l.entries.push_back({glm::vec3(colour), meaning});
  return l;
}

std::vector<glm::vec4> PostProjectiveView::drawLines(const ShadowContext& c, const ShadowTechnique& t, int light,
                                                     const glm::dmat4& camera, const glm::mat4& view) {
  psm::PostProjectiveShapes shapes;
  addFrame(shapes, camera, psm::homogeneousLight(c.lights[std::size_t(light)]));
  if (const auto* s = dynamic_cast<const PostProjectiveSubject*>(&t)) s->describePostProjective(c, light, shapes);
  // Two vertices a segment for lines.geom; six (corners 0 1 2, 1 3 2, each with both ends) for
  // lines_quad.vert.
  struct V {
    glm::vec4 a, b, c;
    float corner;
  };
  const bool quads = !gl::caps().geometryShaders;
  std::vector<V> v;
  v.reserve(shapes.lines().size() * (quads ? 6 : 2));
  std::vector<glm::vec4> colours;
  for (const auto& l : shapes.lines()) {
    if (std::find(colours.begin(), colours.end(), l.colour) == colours.end()) colours.push_back(l.colour);
    // Scaled to a common length first: a far point's huge coordinates would lose float digits.
    const double sa = std::max(glm::length(l.a), 1e-300), sb = std::max(glm::length(l.b), 1e-300);
    const glm::vec4 a(l.a / sa), b(l.b / sb);
    if (quads)
      for (int corner : {0, 1, 2, 1, 3, 2}) v.push_back({a, b, l.colour, float(corner)});
    else v.push_back({a, b, l.colour, 0.0f}), v.push_back({b, a, l.colour, 0.0f});
  }
  glBindVertexArray(linesVao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, lineVertices_.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(V)), v.data(), GL_STREAM_DRAW);
  const auto attribute = [](GLuint index, int size, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(V), reinterpret_cast<void*>(offset));
  };
  // lines.geom's program: position (a) and colour; lines_quad.vert's: both ends, colour, corner.
  attribute(0, 4, offsetof(V, a));
  if (quads) attribute(1, 4, offsetof(V, b)), attribute(2, 4, offsetof(V, c)), attribute(3, 1, offsetof(V, corner));
  else attribute(1, 4, offsetof(V, c));
  const float aspect = float(target_.width) / float(target_.height);
  gl::Program& lines = linesProgram();
  lines.use();
  lines.set(quads ? "uViewProj" : "uDisplay", glm::perspective(0.7f, aspect, 0.05f, 500.0f) * view);
  lines.set("uViewport", glm::vec2(float(target_.width), float(target_.height)));
  lines.set("uWidth", LineRenderer::projectorWidth(c.frame.height));
  glDepthFunc(GL_LEQUAL);
  for (const float sign : {1.0f, -1.0f}) {
    lines.set("uSign", sign);
    glDrawArrays(quads ? GL_TRIANGLES : GL_LINES, 0, GLsizei(v.size()));
  }
  glDepthFunc(GL_LESS);
  glBindVertexArray(0);
  return colours;
}

void PostProjectiveView::draw(const ShadowContext& c, const ShadowTechnique& t, std::vector<Inset>& insets,
                              std::vector<Legend>& legends, int light) {
  if (mode_ == Mode::Off || c.frame.godView || c.lights.empty()) return;
  auto timer = gl::TimerScope(c.timers, "post-projective view");
  if (light < 0) light = std::min(light_, int(c.lights.size()) - 1);
  const Inset corner = inset(c.frame.width, c.frame.height).value_or(Inset{"", 0, 0, c.frame.width, c.frame.height});
  const int w = corner.width, h = corner.height;
  if (target_.width != w || target_.height != h) target_ = gl::makeRenderTarget(w, h, "post-projective view");
  const auto* subject = dynamic_cast<const PostProjectiveSubject*>(&t);
  const glm::dmat4 camera = subject ? subject->postProjectiveCamera(c, light) : glm::dmat4(c.viewerViewProj());
  const glm::mat4 view = displayView();

  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo.id());
  glViewport(0, 0, w, h);
  glClearColor(0.09f, 0.1f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // The clip planes (post_projective.vert); without gl_ClipDistance the shaders discard instead.
  const bool clip = gl::caps().clipDistance;
  for (int k = 0; k < 7 && clip; ++k) glEnable(GLenum(GL_CLIP_DISTANCE0 + k));
  drawScene(c, glm::mat4(camera), view);
  for (int k = 1; k < 7 && clip; ++k) glDisable(GLenum(GL_CLIP_DISTANCE0 + k));
  legends.push_back(postProjectiveLegend(drawLines(c, t, light, camera, view)));
  if (clip) glDisable(GL_CLIP_DISTANCE0);
  composite(c, corner.x, corner.y, w, h);
  if (const auto i = inset(c.frame.width, c.frame.height)) insets.push_back(*i);
}

std::optional<Inset> PostProjectiveView::inset(int frameWidth, int frameHeight) const {
  if (mode_ != Mode::Inset) return std::nullopt;
  const int w = std::max(16, int(float(frameWidth) * size_));
  const int h = std::max(16, w * frameHeight / std::max(frameWidth, 1));
  return Inset{"post-projective view inset", 8, 8, w, h};
}

// Into the frame without touching a measurement's attachments: the surfaces under the inset stay
// measured (app/measurement.hpp).
void PostProjectiveView::composite(const ShadowContext& c, int x, int y, int w, int h) {
  glBindFramebuffer(GL_FRAMEBUFFER, c.frame.framebuffer);
  glDisable(GL_DEPTH_TEST);
  withoutMeasurement([&] {
    if (x > 0) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(x - 2, y - 2, w + 4, h + 4);
      glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
    }
    glViewport(x, y, w, h);
    blit_.use();
    blit_.set("uOverlay", 0);
    blit_.set("uOpacity", 1.0f);
    blit_.set("uFlip", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, target_.color.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  });
  glBindVertexArray(0);
  glViewport(0, 0, c.frame.width, c.frame.height);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab::tech

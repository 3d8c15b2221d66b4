#include "stencil_volumes.hpp"

#include <algorithm>
#include <cmath>

#include "app/measurement.hpp"
#include "gl/caps.hpp"
#include "gl/scene_draw.hpp"
#include "technique/scene_cache.hpp"

namespace shadowlab::tech {
namespace {

using P = StencilVolumeParams;

GLenum toGl(volume::StencilOp op) {
  return op == volume::StencilOp::IncrWrap ? GL_INCR_WRAP : op == volume::StencilOp::DecrWrap ? GL_DECR_WRAP : GL_KEEP;
}

}  // namespace

void StencilVolumes::declare(ParamRegistry& r, const std::string& n) {
  r.addChoice(n + "view", &p_.view, {"lit", "volumes", "wireframe", "stencil", "silhouettes"}, "the inner buffers");
  r.add(n + "view_light", &p_.viewLight, 0, 3, "which light's volumes, stencil counts and silhouettes the views show");
  r.addChoice(n + "method", &p_.method, {"auto", "z_pass", "z_fail"},
              "auto: z-fail only for casters whose volume can reach the near plane");
  r.addChoice(n + "silhouettes", &p_.silhouettes, {"cpu", "gpu"},
              "CPU from the adjacency (cached), or a geometry shader with triangles_adjacency");
  r.add(n + "two_sided", &p_.twoSided,
        "glStencilOpSeparate: front and back faces in one pass (else two culled passes)");
  r.addChoice(n + "far", &p_.far, {"infinite", "depth_clamp"},
              "infinite far plane, or a finite one with GL_DEPTH_CLAMP");
  r.addChoice(n + "open_meshes", &p_.openMeshes, {"skip", "z_pass_only"},
              "open meshes cannot close a volume: cast nothing, or z-pass without caps");
  r.add(n + "scissor", &p_.scissor, "limit each point/spot light's passes to the screen rectangle of its reach");
  r.add(n + "fill_query", &p_.fillQuery, "an extra pass counting every volume fragment (samples passed), timed apart");
}

void StencilVolumes::init() {
  for (gl::Program* p : {&ambient_, &volume_, &heat_}) p->build();
  if (gl::caps().geometryShaders) volumeGs_.build();  // WebGL2 has none: silhouettes=gpu runs on the CPU
  emptyVao_ = gl::makeVertexArray("volumes: fullscreen triangle");
  lineVao_ = gl::makeVertexArray("volumes: silhouette lines");
  lineBuffer_ = gl::makeBuffer(GL_ARRAY_BUFFER, "volumes: silhouette lines");
}

bool StencilVolumes::casts(std::size_t o) const { return o < casting_.size() && casting_[o]; }
bool StencilVolumes::gpuSilhouettes() const {
  return p_.silhouettes == P::Silhouettes::Gpu && gl::caps().geometryShaders;
}
bool StencilVolumes::depthClamp() const { return p_.far == P::FarPlane::DepthClamp && gl::caps().depthClamp; }

// ==== 0. edge adjacency, once per mesh: silhouettes later, closedness now =====================
void StencilVolumes::buildAdjacency(const SceneCache& cache) {
  const Scene& scene = cache.scene();
  adjacency_.clear();
  adjacencyGpu_.clear();
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    adjacency_.push_back(volume::buildAdjacency(scene.meshes[m]));
    const volume::EdgeAdjacency& a = adjacency_.back();
    AdjacencyMesh g{gl::makeVertexArray("adjacency " + std::to_string(m)),
                    gl::makeBuffer(GL_ARRAY_BUFFER, "adjacency vertices"),
                    gl::makeBuffer(GL_ELEMENT_ARRAY_BUFFER, "adjacency indices"), GLsizei(a.adjacencyIndices.size())};
    glBindVertexArray(g.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(a.positions.size() * sizeof(glm::vec3)), a.positions.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(a.adjacencyIndices.size() * 4), a.adjacencyIndices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    adjacencyGpu_.push_back(std::move(g));
  }
  adjacencyRevision_ = cache.revision();
  caches_.clear();
}

void StencilVolumes::render(const ShadowContext& c) {
  if (c.scene.revision() != adjacencyRevision_) buildAdjacency(c.scene);
  // Which objects cast: closed meshes, and open ones only when drawn z-pass.
  const Scene& scene = c.scene.scene();
  casting_.assign(scene.objects.size(), 0);
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& obj = scene.objects[o];
    casting_[o] = obj.castsShadow && (adjacency_[obj.mesh].closed() || p_.openMeshes == P::OpenMeshes::ZPassOnly);
  }
  caches_.resize(std::max<std::size_t>(c.lights.size(), 4));
  while (fill_.size() < caches_.size()) fill_.push_back({gl::makeQuery("fill light " + std::to_string(fill_.size()))});
}

// The CPU path: silhouettes and caps per caster in its own space (the light taken there), then
// moved to world space, all casters of one light in one buffer.
void StencilVolumes::buildVolumes(const ShadowContext& c, VolumeCache& cache, const glm::vec4& L) {
  const std::uint64_t key = c.scene.revision() * 4 + (student.isSilhouette ? 2 : 0) + std::uint64_t(p_.openMeshes);
  if (cache.key == key && cache.light == L) return;
  auto t = gl::TimerScope(c.timers, "cpu volumes");
  volume::buildSceneVolumes(
      c.scene.scene(), adjacency_, L, [this](std::size_t o) { return casts(o); }, student.isSilhouette, cache);
  if (!cache.vao) {
    cache.vao = gl::makeVertexArray("volumes");
    cache.buffer = gl::makeBuffer(GL_ARRAY_BUFFER, "volumes");
  }
  glBindVertexArray(cache.vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, cache.buffer.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cache.triangles.size() * sizeof(glm::vec4)), cache.triangles.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
  cache.light = L;
  cache.key = key;
}

void StencilVolumes::renderLit(const ShadowContext& c, const LitSettings& lit) {
  const Frame f = beginFrame(c);
  depthAndAmbient(f, lit);
  for (int i = 0; i < int(c.lights.size()); ++i) renderLight(f, i, lit);
  finishFrame(f);
}

StencilVolumes::Frame StencilVolumes::beginFrame(const ShadowContext& c) {
  const FrameInfo& fi = c.frame;
  const float aspect = float(fi.width) / float(fi.height);
  Frame f{c};
  glm::mat4 proj = fi.projection;
  if (!depthClamp())  // far=infinite, or no depth clamp here (WebGL2 without EXT_depth_clamp)
    proj = student.infinitePerspective && !fi.godView
               ? student.infinitePerspective(c.viewer.fovY, aspect, c.viewer.nearZ, volume::kInfiniteEpsilon)
               : volume::makeFarInfinite(fi.projection);
  f.viewProj = proj * fi.view;
  f.nearRect = volume::nearRect(c.viewer.view(), c.viewer.fovY, aspect, c.viewer.nearZ);
  zPassCount_ = zFailCount_ = 0;
  volumeTriangles_ = 0;
  return f;
}

// ==== 4. views: the volumes, their wireframe, the silhouettes (and the god view's lines) =======
void StencilVolumes::finishFrame(const Frame& f) {
  const ShadowContext& c = f.c;
  const FrameInfo& fi = c.frame;
  const VolumeCache& shown = caches_[std::size_t(std::clamp(p_.viewLight, 0, int(caches_.size()) - 1))];
  if (p_.view == P::View::Volumes || p_.view == P::View::Wireframe) {
    auto t = gl::TimerScope(c.timers, "volumes view");
    drawVolumesView(shown, f.viewProj);
  }
  if (p_.view == P::View::Silhouettes || fi.godView) {
    auto t = gl::TimerScope(c.timers, "silhouettes view");
    drawSilhouettes(shown, f.viewProj);
  }
  pushGodViewShapes(c, shown);
  if (fi.godView) return;
  std::size_t open = 0, openEdges = 0;  // open edges: boundary, non-manifold and flipped ones, per object
  const Scene& scene = c.scene.scene();
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const volume::EdgeAdjacency& a = adjacency_[scene.objects[o].mesh];
    open += !a.closed();
    openEdges += a.boundaryEdges + a.nonManifoldEdges + a.inconsistentEdges;
  }
  stats_ = {};
  stats_.culls = false;
  stats_.triangles = volumeTriangles_;
  stats_.extra = {{"z-pass objects", std::to_string(zPassCount_)},
                  {"z-fail objects", std::to_string(zFailCount_)},
                  {"open meshes", std::to_string(open) +
                                      (p_.openMeshes == P::OpenMeshes::Skip ? " (cast nothing)" : " (z-pass only)")},
                  {"open edges", std::to_string(openEdges)},
                  {"silhouette edges", std::to_string(shown.silhouette.size() / 2)}};
  // What the parameters ask for and this context cannot do (WebGL2): said, never silently swapped.
  if (p_.silhouettes == P::Silhouettes::Gpu && !gpuSilhouettes())
    stats_.extra.push_back({"silhouettes", "on the CPU: no geometry shaders in WebGL2"});
  if (p_.far == P::FarPlane::DepthClamp && !depthClamp())
    stats_.extra.push_back({"far", "infinite: no EXT_depth_clamp here"});
  if (p_.view == P::View::Wireframe && !gl::caps().polygonMode)
    stats_.extra.push_back({"wireframe", "drawn filled: this browser has no WEBGL_polygon_mode"});
  if (p_.fillQuery && gl::caps().gles) stats_.extra.push_back({"fill query", "none: WebGL2 counts no samples"});
  for (std::size_t i = 0; i < c.lights.size(); ++i) {
    stats_.bytes += caches_[i].triangles.size() * sizeof(glm::vec4);
    if (c.lights[i].enabled && p_.fillQuery && !gl::caps().gles)
      stats_.extra.push_back({"fill light" + std::to_string(i), std::to_string(fill_[i].samples)});
  }
}

// ==== 1. depth and ambient ======================================================================
void StencilVolumes::depthAndAmbient(const Frame& f, const LitSettings& lit) {
  auto t = gl::TimerScope(f.c.timers, "depth + ambient");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glClearColor(0.05f, 0.06f, 0.08f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  ambient_.use();
  ambient_.set("uAmbient", lit.ambient);
  drawScene(f, ambient_, lit);
}

void StencilVolumes::renderLight(const Frame& frame, int i, const LitSettings& lit) {
  const ShadowContext& c = frame.c;
  const Light& light = c.lights[std::size_t(i)];
  // A disabled light that is being measured still gets its count (its V), but adds no colour.
  if (!light.enabled && i != c.frame.measureLight) return;
  if (p_.view == P::View::Stencil && i != p_.viewLight) return;
  const glm::vec4 L = volume::homogeneousLight(light);
  VolumeCache& cache = caches_[std::size_t(i)];
  if (!gpuSilhouettes() || p_.view == P::View::Silhouettes || i == p_.viewLight) buildVolumes(c, cache, L);
  // Which casters need z-fail: their volume can reach the viewer's near plane.
  Frame f = frame;
  f.zFail.assign(casting_.size(), 0);
  const Scene& scene = c.scene.scene();
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (!casts(o)) continue;
    const bool open = !adjacency_[scene.objects[o].mesh].closed();
    const Aabb box = c.scene.boxes()[o];
    const bool reach = open                        ? false
                       : student.mayReachNearPlane ? student.mayReachNearPlane(box, f.nearRect, L)
                                                   : volume::volumeMayReachNearPlane(box, f.nearRect, L);
    f.zFail[o] = p_.method == P::Method::ZFail ? !open : p_.method == P::Method::ZPass ? 0 : reach;
    (f.zFail[o] ? zFailCount_ : zPassCount_) += 1;
  }
  // The measured light is never scissored: outside its reach V would stay 0 and read as shadow.
  if (p_.scissor && light.kind != LightKind::Directional && i != c.frame.measureLight) {
    const auto s =
        volume::scissorForSphere(light.position, volume::lightReach(light), f.viewProj, c.frame.width, c.frame.height);
    if (s.width <= 0 || s.height <= 0) return;  // wholly off screen: nothing to light
    glEnable(GL_SCISSOR_TEST);
    glScissor(s.x, s.y, s.width, s.height);
  }
  countStencil(f, i, cache, L);
  if (p_.fillQuery && !c.frame.godView && !gl::caps().gles) {  // WebGL2 counts no samples
    auto t = gl::TimerScope(c.timers, "fill query");
    measureFill(f, i, cache, L);
  }
  litPass(f, i, lit);
  if (p_.view == P::View::Stencil) drawStencilHeatmap();
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
}

// ==== 2. stencil counting =======================================================================
void StencilVolumes::countStencil(const Frame& f, int i, const VolumeCache& cache, const glm::vec4& L) {
  auto t = gl::TimerScope(f.c.timers, "stencil light" + std::to_string(i));
  glClear(GL_STENCIL_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  if (depthClamp()) glEnable(GL_DEPTH_CLAMP);
  for (bool fail : {false, true}) {
    const volume::StencilOps ops = student.stencilOps ? student.stencilOps(fail) : volume::stencilOps(fail);
    auto set = [](GLenum face, const volume::FaceStencilOps& o) {
      glStencilOpSeparate(face, toGl(o.stencilFail), toGl(o.depthFail), toGl(o.depthPass));
    };
    if (p_.twoSided) {  // both faces in one pass: no culling, an op per face orientation
      glDisable(GL_CULL_FACE);
      set(GL_FRONT, ops.front);
      set(GL_BACK, ops.back);
      drawVolumes(f, cache, L, fail);
    } else {  // two passes: front faces with the front ops, then back faces with the back ops
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
      set(GL_FRONT_AND_BACK, ops.front);
      drawVolumes(f, cache, L, fail);
      glCullFace(GL_FRONT);
      set(GL_FRONT_AND_BACK, ops.back);
      drawVolumes(f, cache, L, fail);
      glCullFace(GL_BACK);
    }
  }
  if (depthClamp()) glDisable(GL_DEPTH_CLAMP);
  glEnable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// ==== 3. lit pass: add the light where the count is 0 ==========================================
void StencilVolumes::litPass(const Frame& f, int i, const LitSettings& lit) {
  auto t = gl::TimerScope(f.c.timers, "lit light" + std::to_string(i));
  const Light& light = f.c.lights[std::size_t(i)];
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthFunc(GL_EQUAL);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  // The measurement attachments (1-3) are overwritten, not summed; only the measured light
  // writes them at all (V = 1 where lit; the ambient pass left 0 everywhere else).
  for (GLuint a = 1; a <= 3; ++a) {
    gl::disableBlendAttachment(a);
    gl::colorMaskAttachment(a, i == f.c.frame.measureLight);
  }
  if (!light.enabled) gl::colorMaskAttachment(0, false);
  const gl::Program& program = lit_.get({"LIGHT_KIND " + std::to_string(int(light.kind))});
  program.use();
  gl::setLight(program, "uLight", light);
  drawScene(f, program, lit);
  for (GLuint a = 0; a <= 3; ++a) gl::colorMaskAttachment(a, true);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
}

// The volumes of every caster whose method is `zFail` (z-fail ones with their caps).
void StencilVolumes::drawVolumes(const Frame& f, const VolumeCache& c, const glm::vec4& L, bool zFail) {
  const Scene& scene = f.c.scene.scene();
  if (gpuSilhouettes()) {
    volumeGs_.use();
    volumeGs_.set("uViewProj", f.viewProj);
    volumeGs_.set("uLight", L);
    volumeGs_.set("uCaps", zFail);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      if (!casts(o) || bool(f.zFail[o]) != zFail) continue;
      const AdjacencyMesh& g = adjacencyGpu_[scene.objects[o].mesh];
      volumeGs_.set("uModel", scene.objects[o].model);
      volumeGs_.set("uTwoSided", !adjacency_[scene.objects[o].mesh].closed());
      glBindVertexArray(g.vao.id());
      glDrawElements(GL_TRIANGLES_ADJACENCY, g.count, GL_UNSIGNED_INT, nullptr);
      gl::countDraws();
      volumeTriangles_ += std::size_t(g.count) / 6;  // triangles in; the geometry shader emits the volume
    }
    return;
  }
  std::vector<GLint> first;
  std::vector<GLsizei> count;
  for (std::size_t o = 0; o < c.first.size(); ++o)
    if (casts(o) && bool(f.zFail[o]) == zFail && c.sides[o] + c.caps[o] > 0) {
      first.push_back(c.first[o]);
      count.push_back(c.sides[o] + (zFail ? c.caps[o] : 0));  // z-pass needs no caps
    }
  if (first.empty()) return;
  for (GLsizei n : count) volumeTriangles_ += std::size_t(n) / 3;
  volume_.use();
  volume_.set("uViewProj", f.viewProj);
  volume_.set("uLight", L);
  volume_.set("uColor", glm::vec4(1));
  glBindVertexArray(c.vao.id());
  glMultiDrawArrays(GL_TRIANGLES, first.data(), count.data(), GLsizei(first.size()));
  gl::countDraws(int(first.size()));
}

// Fill cost: every fragment the volumes rasterise (depth test off, nothing written), counted by
// an occlusion query. Read a frame later, when it is ready, so the CPU never waits.
void StencilVolumes::measureFill(const Frame& f, int i, const VolumeCache& c, const glm::vec4& L) {
  Fill& fl = fill_[std::size_t(i)];
  GLuint ready = 0;
  if (fl.issued) glGetQueryObjectuiv(fl.query.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
  if (ready) glGetQueryObjectuiv(fl.query.id(), GL_QUERY_RESULT, &fl.samples);
  if (fl.issued && !ready) return;
  // Nothing the count depends on changed (a still camera under a still light): the pass that would
  // count the same fragments again is skipped, as a map nothing invalidated is kept.
  PassKey key;
  key << c.key << f.c.scene.revision() << f.viewProj << L << p_ << f.c.frame.width << f.c.frame.height
      << f.c.lights[std::size_t(i)] << f.c.frame.measureLight << bool(student.isSilhouette)
      << bool(student.mayReachNearPlane);
  for (int z : f.zFail) key << z;
  if (fl.issued && key == fl.counted) return;
  fl.counted = std::move(key);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthFunc(GL_ALWAYS);
  glDisable(GL_CULL_FACE);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glBeginQuery(GL_SAMPLES_PASSED, fl.query.id());
  for (bool fail : {false, true}) drawVolumes(f, c, L, fail);
  glEndQuery(GL_SAMPLES_PASSED);
  fl.issued = true;
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

namespace {
// The stencil counts 1..5; 0 shows the frame; anything else (6+, wrapped negatives) is kOtherCount.
constexpr glm::vec3 kCountRamp[] = {
    {0.1f, 0.1f, 0.6f}, {0.1f, 0.6f, 0.9f}, {0.2f, 0.8f, 0.3f}, {0.9f, 0.9f, 0.2f}, {1.0f, 0.5f, 0.1f}};
constexpr glm::vec3 kOtherCount{0.9f, 0.1f, 0.1f};
}  // namespace

std::optional<Legend> StencilVolumes::legend() const {
  if (p_.view != StencilVolumeParams::View::Stencil) return std::nullopt;
  Legend l{"stencil count: volumes entered minus left (0: lit)", {}};
  for (int k = 1; k <= 5; ++k) l.entries.push_back({kCountRamp[k - 1], std::to_string(k)});
  l.entries.push_back({kOtherCount, "6 and more, or negative (a broken volume)"});
  return l;
}

// The stencil count as colours: one full-screen triangle per count, where the stencil equals it.
void StencilVolumes::drawStencilHeatmap() {
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  heat_.use();
  glBindVertexArray(emptyVao_.id());
  withoutMeasurement([&] {
    for (int k = 0; k <= 5; ++k) {  // k = 0: every count not listed (6+, and wrapped negatives) in red
      glStencilFunc(k == 0 ? GL_NOTEQUAL : GL_EQUAL, k, 0xff);
      heat_.set("uColor", glm::vec4(k == 0 ? kOtherCount : kCountRamp[k - 1], 0.7f));
      glDrawArrays(GL_TRIANGLES, 0, 3);
      gl::countDraws();
    }
  });
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

void StencilVolumes::drawVolumesView(const VolumeCache& c, const glm::mat4& viewProj) {
  const bool wire = p_.view == P::View::Wireframe;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  if (wire && gl::caps().polygonMode) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  volume_.use();
  volume_.set("uViewProj", viewProj);
  volume_.set("uLight", c.light);
  volume_.set("uColor", glm::vec4(1.0f, 0.85f, 0.2f, wire ? 0.9f : 0.18f));
  glBindVertexArray(c.vao.id());
  withoutMeasurement([&] { glDrawArrays(GL_TRIANGLES, 0, GLsizei(c.triangles.size())); });
  gl::countDraws();
  if (gl::caps().polygonMode) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

// The silhouette edges as lines (the volume shader draws w = 1 points where they are).
void StencilVolumes::drawSilhouettes(const VolumeCache& c, const glm::mat4& viewProj) {
  std::vector<glm::vec4> v;
  for (const glm::vec3& p : c.silhouette) v.push_back(glm::vec4(p, 1));
  glBindVertexArray(lineVao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(glm::vec4)), v.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  withoutMeasurement([&] {
    glDepthFunc(GL_LEQUAL);
    volume_.use();
    volume_.set("uViewProj", viewProj);
    volume_.set("uColor", glm::vec4(1.0f, 0.2f, 0.9f, 1.0f));
    glDrawArrays(GL_LINES, 0, GLsizei(v.size()));
    gl::countDraws();
    glDepthFunc(GL_LESS);
  });
}

// The god view: the shown light's silhouette and a stub of each side quad toward infinity.
void StencilVolumes::pushGodViewShapes(const ShadowContext& c, const VolumeCache& v) const {
  const std::size_t step = std::max<std::size_t>(1, v.silhouette.size() / 4000) * 2;
  for (std::size_t k = 0; k + 1 < v.silhouette.size(); k += step) {
    const glm::vec3 a = v.silhouette[k], b = v.silhouette[k + 1];
    c.debug.line(a, b, {1.0f, 0.2f, 0.9f, 1.0f});
    const glm::vec3 dir =
        v.light.w != 0.0f ? glm::normalize(a - glm::vec3(v.light) / v.light.w) : -glm::normalize(glm::vec3(v.light));
    c.debug.line(a, a + 6.0f * dir, {1.0f, 0.85f, 0.2f, 0.5f});
  }
  c.debug.name({1.0f, 0.2f, 0.9f, 1.0f}, "silhouette edges");
  c.debug.name({1.0f, 0.85f, 0.2f, 0.5f}, "their extrusion away from the light");
}

void StencilVolumes::drawScene(const Frame& f, const gl::Program& prog, const LitSettings& lit) {
  prog.set("uViewProj", f.viewProj);
  prog.set("uEye", f.c.frame.eye);
  prog.set("uTexture", 0);
  gl::SceneDrawOptions draw;
  draw.specular = lit.specular;
  draw.shininess = lit.shininess;
  gl::drawScene(prog, f.c.scene.scene(), f.c.scene.gpu(), draw);
}

}  // namespace shadowlab::tech

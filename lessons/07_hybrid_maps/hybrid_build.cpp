#include "hybrid_build.hpp"

#include <stdexcept>

#include "gl/caps.hpp"
#include "gl/texture.hpp"

namespace shadowlab::tech {
namespace {

// The words of a width x height unsigned-integer texture (GL_RED_INTEGER: R32UI, one a texel;
// GL_RGBA_INTEGER: RGBA32UI, four). Without glGetTexImage (WebGL2) through a framebuffer, as a
// colour target: OpenGL ES reads an integer target only as RGBA_INTEGER, so one-channel texels come back
// four words wide and are packed here.
std::vector<std::uint32_t> readTexture(GLuint texture, GLenum format, int width, int height) {
  const std::size_t perTexel = format == GL_RED_INTEGER ? 1 : 4;
  std::vector<std::uint32_t> out(std::size_t(width) * std::size_t(height) * perTexel);
  if (gl::caps().getTexImage) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_INT, out.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return out;
  }
  GLint bound = 0;  // the caller's framebuffer, bound again after
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  const gl::Framebuffer fbo = gl::makeFramebuffer("hybrid map: read back");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  std::vector<std::uint32_t> rgba(std::size_t(width) * std::size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(bound));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = rgba[(i / perTexel) * 4 + (perTexel == 1 ? 0 : i % 4)];
  return out;
}

}  // namespace

HybridBuilder::HybridBuilder(std::string label)
    : label_(std::move(label)),
      merge_(label_ + ": merge sweep", {"common/fullscreen.vert", "07_hybrid_maps/merge.frag"}),
      count_(label_ + ": count pyramid", {"common/fullscreen.vert", "07_hybrid_maps/count.frag"}),
      starts_(label_ + ": record starts", {"common/fullscreen.vert", "07_hybrid_maps/starts.frag"}),
      rootPass_(label_ + ": root grid", {"common/fullscreen.vert", "07_hybrid_maps/root.frag"}),
      recordsPass_(label_ + ": records", {"07_hybrid_maps/records.vert", "07_hybrid_maps/records.frag"}) {}

void HybridBuilder::init() {
  for (gl::Program* p : {&merge_, &count_, &starts_, &rootPass_, &recordsPass_}) {
    p->keepUnderFloor();  // the sweep's counts size the records: data, not shading
    p->build();
  }
  vao_ = gl::makeVertexArray(label_ + ": passes");
  fbo_ = gl::makeFramebuffer(label_ + ": passes");
  const std::uint32_t zero[4] = {0, 0, 0, 0};
  dummyUint_ = gl::makeTexelGrid(GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 1, 1, label_ + ": no counts", zero);
}

// ---- textures ---------------------------------------------------------------------------------------

namespace {

// The record texture for `records` records: rows of kRecordRow, none when there are none.
void allocateRecords(HybridMapGpu& map, std::uint32_t records, const std::string& label) {
  constexpr int row = HybridMapGpu::kRecordRow;
  const int rows = int((records + row - 1) / row);
  if (rows == 0) {
    map.records.reset();
    map.recordRows = 0;
    return;
  }
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (rows > maxSize)
    throw std::runtime_error(label + ": " + std::to_string(records) + " records need " + std::to_string(rows) +
                             " rows, more than GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
  if (rows == map.recordRows && map.records) return;
  map.recordRows = rows;
  map.records = gl::makeTexelGrid(GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, row, rows, label + ": records");
}

}  // namespace

std::uint64_t HybridMapGpu::storedBytes() const {
  return 4 * std::uint64_t(rootSize) * std::uint64_t(rootSize) +
         16 * std::uint64_t(kRecordRow) * std::uint64_t(recordRows);
}

void HybridBuilder::allocate(HybridMapGpu& map, int size, int levels) {
  map.sourceSize = size;
  map.levels = levels;
  if (size != map.allocatedSize || levels != map.allocatedLevels) {
    map.allocatedSize = size;
    map.allocatedLevels = levels;
    map.pyramid.clear();
    map.pyramid.emplace_back().size = size;
    map.workBytes = 0;
    // Levels 1 .. top: halving (rounding up) until one texel, and at least to the root level.
    // Levels 0 has no index: the root grid is the map.
    while (levels > 0 && (map.pyramid.back().size > 1 || int(map.pyramid.size()) <= levels)) {
      HybridMapGpu::Level l;
      l.size = hybrid::halvedSize(map.pyramid.back().size);
      const std::string n = label_ + ": level " + std::to_string(map.pyramid.size());
      if (int(map.pyramid.size()) <= levels)
        l.values = gl::makeTexelGrid(GL_R32F, GL_RED, GL_FLOAT, l.size, l.size, n + " merge grid");
      l.counts = gl::makeTexelGrid(GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, l.size, l.size, n + " counts");
      l.starts = gl::makeTexelGrid(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, l.size, l.size, n + " record starts");
      map.workBytes += std::uint64_t(l.size) * std::uint64_t(l.size) * ((l.values ? 4 : 0) + 16 + 4);
      map.pyramid.push_back(std::move(l));
    }
  }
  const int rootSize = map.pyramid[std::size_t(levels)].size;
  if (rootSize != map.rootSize || !map.root) {
    map.rootSize = rootSize;
    map.root = gl::makeTexelGrid(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, rootSize, rootSize, label_ + ": root grid");
  }
}

void HybridBuilder::attach(std::initializer_list<GLuint> colour, int width, int height) {
  GLenum buffers[2] = {GL_NONE, GL_NONE};
  int i = 0;
  for (GLuint t : colour) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, t, 0);
    buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    ++i;
  }
  for (int j = i; j < 2; ++j)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + j), GL_TEXTURE_2D, 0, 0);
  glDrawBuffers(i, buffers);
  glViewport(0, 0, width, height);
}

// ---- the passes -------------------------------------------------------------------------------------

// 1. the merge sweep, level by level, each level's records per subtree beside it
void HybridBuilder::sweep(const gl::ShadowMap& depth, const hybrid::MergeRule& rule, HybridMapGpu& map) {
  merge_.use();
  merge_.set("uChildren", 0);
  merge_.set("uChildCounts", 1);
  merge_.set("uCriterion", int(rule.criterion));
  merge_.set("uEps0", rule.eps0);
  merge_.set("uMaxSlope", rule.maxSlope);
  merge_.set("uPerspective", rule.space.perspective);
  merge_.set("uNear", rule.space.nearZ);
  merge_.set("uFar", rule.space.farZ);
  merge_.set("uTexel", rule.space.texel);
  for (int k = 1; k <= map.levels; ++k) {
    const HybridMapGpu::Level& child = map.pyramid[std::size_t(k) - 1];
    const HybridMapGpu::Level& l = map.pyramid[std::size_t(k)];
    attach({l.values.id(), l.counts.id()}, l.size, l.size);
    gl::bindTexelUnit(0, k == 1 ? depth.texture.id() : child.values.id());
    gl::bindTexelUnit(1, k == 1 ? dummyUint_.id() : child.counts.id());
    merge_.set("uLevel", k);
    merge_.set("uChildSize", child.size);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
}

// 2.-3. the counts up to one texel, then each texel's first record, top down
void HybridBuilder::countAndStarts(HybridMapGpu& map) {
  const std::vector<HybridMapGpu::Level>& p = map.pyramid;
  const int top = int(p.size()) - 1;
  count_.use();
  count_.set("uChildCounts", 0);
  for (int k = map.levels + 1; k <= top; ++k) {
    attach({p[std::size_t(k)].counts.id()}, p[std::size_t(k)].size, p[std::size_t(k)].size);
    gl::bindTexelUnit(0, p[std::size_t(k) - 1].counts.id());
    count_.set("uChildSize", p[std::size_t(k) - 1].size);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  attach({p[std::size_t(top)].starts.id()}, 1, 1);
  const GLuint zero[4] = {0, 0, 0, 0};
  glClearBufferuiv(GL_COLOR, 0, zero);
  starts_.use();
  starts_.set("uParentStarts", 0);
  starts_.set("uParentValues", 1);
  starts_.set("uCounts", 2);
  for (int k = top - 1; k >= 1; --k) {
    const HybridMapGpu::Level& parent = p[std::size_t(k) + 1];
    const HybridMapGpu::Level& l = p[std::size_t(k)];
    attach({l.starts.id()}, l.size, l.size);
    const bool owns = k + 1 <= map.levels;
    gl::bindTexelUnit(0, parent.starts.id());
    gl::bindTexelUnit(1, owns ? parent.values.id() : 0);
    gl::bindTexelUnit(2, l.counts.id());
    starts_.set("uParentOwns", owns);
    starts_.set("uSize", l.size);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  // The total and the records per level: the record texture's size, and the header's figures.
  const auto total = readTexture(p[std::size_t(top)].counts.id(), GL_RGBA_INTEGER, 1, 1);
  map.recordCount = total[0];
  map.recordsAt = {0, total[1], total[2], total[3]};
}

// 4. the root grid
void HybridBuilder::writeRoot(const gl::ShadowMap& depth, HybridMapGpu& map) {
  attach({map.root.id()}, map.rootSize, map.rootSize);
  rootPass_.use();
  rootPass_.set("uValues", 0);
  rootPass_.set("uStarts", 1);
  rootPass_.set("uHasRecords", map.levels >= 1);
  const HybridMapGpu::Level& l = map.pyramid[std::size_t(map.levels)];
  gl::bindTexelUnit(0, map.levels >= 1 ? l.values.id() : depth.texture.id());
  gl::bindTexelUnit(1, map.levels >= 1 ? l.starts.id() : dummyUint_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

// 5. the records, one point per texel of each level
void HybridBuilder::writeRecords(const gl::ShadowMap& depth, HybridMapGpu& map) {
  allocateRecords(map, map.recordCount, label_);
  if (map.recordCount == 0) return;
  attach({map.records.id()}, HybridMapGpu::kRecordRow, map.recordRows);
  recordsPass_.use();
  recordsPass_.set("uValues", 0);
  recordsPass_.set("uStarts", 1);
  recordsPass_.set("uChildValues", 2);
  recordsPass_.set("uChildStarts", 3);
  recordsPass_.set("uRowWidth", HybridMapGpu::kRecordRow);
  recordsPass_.set("uRows", map.recordRows);
  for (int k = 1; k <= map.levels; ++k) {
    const HybridMapGpu::Level& l = map.pyramid[std::size_t(k)];
    const HybridMapGpu::Level& child = map.pyramid[std::size_t(k) - 1];
    gl::bindTexelUnit(0, l.values.id());
    gl::bindTexelUnit(1, l.starts.id());
    gl::bindTexelUnit(2, k == 1 ? depth.texture.id() : child.values.id());
    gl::bindTexelUnit(3, k == 1 ? dummyUint_.id() : child.starts.id());
    recordsPass_.set("uLevel", k);
    recordsPass_.set("uSize", l.size);
    recordsPass_.set("uChildSize", child.size);
    glDrawArrays(GL_POINTS, 0, l.size * l.size);
  }
}

namespace {
template <class F>
void timed(gl::GpuTimers* timers, const std::string& pass, F&& f) {
  if (!timers) return f();
  gl::TimerScope t(*timers, pass);
  f();
}
}  // namespace

void HybridBuilder::build(const gl::ShadowMap& depth, const hybrid::MergeRule& rule, int levels, HybridMapGpu& map,
                          gl::GpuTimers* timers, const std::string& suffix) {
  if (levels < 0 || levels > hybrid::kMaxLevels)
    throw std::invalid_argument(label_ + ": levels = " + std::to_string(levels) + " is not in 0..3");
  if (depth.cube) throw std::invalid_argument(label_ + ": a cube map has no hybrid map");
  allocate(map, depth.size, levels);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindVertexArray(vao_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  map.recordCount = 0;
  map.recordsAt = {};
  if (levels >= 1) {
    timed(timers, "hybrid merge" + suffix, [&] { sweep(depth, rule, map); });
    timed(timers, "hybrid index" + suffix, [&] { countAndStarts(map); });
  }
  timed(timers, "hybrid records" + suffix, [&] {
    writeRoot(depth, map);
    writeRecords(depth, map);
  });
  for (int u = 0; u < 4; ++u) gl::bindTexelUnit(u, 0);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
}

void HybridBuilder::upload(const hybrid::HybridMap& source, HybridMapGpu& map) {
  map.sourceSize = source.sourceSize;
  map.levels = source.levels;
  map.rootSize = source.rootSize;
  map.root = gl::makeTexelGrid(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, source.rootSize, source.rootSize,
                               "hybrid map: root grid (uploaded)", source.root.data());
  map.recordCount = std::uint32_t(source.records.size());
  allocateRecords(map, map.recordCount, "hybrid map (uploaded)");
  if (map.records) {
    std::vector<std::array<std::uint32_t, 4>> padded(std::size_t(map.recordRows) * HybridMapGpu::kRecordRow);
    std::copy(source.records.begin(), source.records.end(), padded.begin());
    glBindTexture(GL_TEXTURE_2D, map.records.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, HybridMapGpu::kRecordRow, map.recordRows, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                    padded.data());
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  const hybrid::HybridCounts counts = hybrid::countHybrid(source);
  for (std::size_t k = 0; k < map.recordsAt.size(); ++k) map.recordsAt[k] = std::uint32_t(counts.recordsAt[k]);
}

hybrid::HybridMap HybridBuilder::download(const HybridMapGpu& map) {
  hybrid::HybridMap out;
  out.sourceSize = map.sourceSize;
  out.levels = map.levels;
  out.rootSize = map.rootSize;
  out.root = readTexture(map.root.id(), GL_RED_INTEGER, map.rootSize, map.rootSize);
  if (!map.records) return out;
  const auto words = readTexture(map.records.id(), GL_RGBA_INTEGER, HybridMapGpu::kRecordRow, map.recordRows);
  out.records.resize(map.recordCount);
  for (std::size_t r = 0; r < map.recordCount; ++r)
    for (std::size_t i = 0; i < 4; ++i) out.records[r][i] = words[4 * r + i];
  return out;
}

shadow::DepthMap HybridBuilder::readDepth(const gl::ShadowMap& depth) {
  build(depth, {}, 0, scratch_);
  const hybrid::HybridMap words = download(scratch_);
  std::vector<float> d(words.root.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = hybrid::leafDepth(words.root[i]);
  return shadow::DepthMap(depth.size, depth.size, std::move(d));
}

}  // namespace shadowlab::tech

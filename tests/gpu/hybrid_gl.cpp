// The hybrid map's GPU passes (lessons/07_hybrid_maps/hybrid_build) against the CPU reference
// (common/algorithms/hybrid_map), on a real headless context: given the same depth map, the GPU's
// root grid and records must equal the CPU's word for word, for every criterion, level count,
// depth format and a size that does not halve evenly; and the GLSL descent
// (shaders/07_hybrid_maps/hybrid_descent.glsl) must find, for every source texel, the depth, level and
// steps hybrid::descend finds. Tolerance: none.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "app/context.hpp"
#include "core/paths.hpp"
#include "gl/debug.hpp"
#include "07_hybrid_maps/hybrid_build.hpp"
#include "test_support.hpp"

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

Context& context() {
  static std::unique_ptr<Context> ctx = [] {
    auto c = createHeadlessContext({64, 64, "hybrid_gpu_tests", true, false});
    gl::installDebugOutput();
    return c;
  }();
  return *ctx;
}

tech::HybridBuilder& builder() {
  context();
  static tech::HybridBuilder b("hybrid test");  // destroyed before the context (made after it)
  static const bool ready = (b.init(), true);
  (void)ready;
  return b;
}

// A depth map with plateaus (a disc of towers), a gentle slope, a far background of 1.0 and a few
// single-texel casters: every level gets merged and kept texels.
std::vector<float> sceneDepths(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> d(std::size_t(n) * std::size_t(n));
  const float cx = u(rng) * float(n), cy = u(rng) * float(n), r = (0.2f + 0.2f * u(rng)) * float(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float dx = float(x) - cx, dy = float(y) - cy;
      float v = dx * dx + dy * dy < r * r ? 0.55f : 0.8f + 0.15f * float(x) / float(n);
      if (y > n - n / 5) v = 1.0f;                   // nothing drawn: the far plane
      if (u(rng) < 0.01f) v = 0.1f + 0.8f * u(rng);  // thin casters
      d[std::size_t(y) * std::size_t(n) + std::size_t(x)] = v;
    }
  return d;
}

gl::ShadowMap uploadDepth(const std::vector<float>& depths, int n, gl::DepthFormat format) {
  gl::ShadowMap map = gl::makeShadowMap(n, format, "hybrid test depth");
  glBindTexture(GL_TEXTURE_2D, map.texture.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, n, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return map;
}

struct Case {
  const char* name;
  hybrid::MergeRule rule;
};

std::vector<Case> cases() {
  hybrid::MergeRule window, linear, slopeOrtho, slopePerspective;
  window.eps0 = 0.02f;
  linear.criterion = hybrid::Criterion::Linear;
  linear.eps0 = 0.05f;
  linear.space = {true, 0.5f, 150.0f, 0.002f};
  slopeOrtho.criterion = hybrid::Criterion::Slope;
  slopeOrtho.maxSlope = 2.0f;
  slopeOrtho.space = {false, 3.0f, 83.0f, 0.04f};
  slopePerspective = slopeOrtho;
  slopePerspective.space = linear.space;
  hybrid::MergeRule paper;  // window depth, eps0 = 0.25
  return {{"window", window},
          {"linear", linear},
          {"slope", slopeOrtho},
          {"slope/perspective", slopePerspective},
          {"paper", paper}};
}

}  // namespace

TEST_CASE("hybrid gpu: the GPU build equals the CPU reference word for word") {
  builder();  // the context first
  std::mt19937_64 rng(test::seedFor("hybrid_gpu.build"));
  int compared = 0, records = 0;
  for (int n : {64, 37, 256})
    for (gl::DepthFormat format : {gl::DepthFormat::Depth32F, gl::DepthFormat::Depth24, gl::DepthFormat::Depth16})
      for (const Case& c : cases())
        for (int levels = 0; levels <= hybrid::kMaxLevels; ++levels) {
          const gl::ShadowMap depth = uploadDepth(sceneDepths(rng, n), n, format);
          tech::HybridMapGpu gpu;
          builder().build(depth, c.rule, levels, gpu);
          // The CPU reads the very depths the GPU swept (quantised by the format, converted as texelFetch does).
          const hybrid::HybridMap cpu = hybrid::buildHybrid(builder().readDepth(depth), c.rule, levels);
          const hybrid::HybridMap back = tech::HybridBuilder::download(gpu);
          const std::string what = std::string(gl::depthFormatName(format)) + " " + c.name;
          INFO("seed ", test::seed(), " size ", n, " ", what, " levels ", levels);
          CHECK(back.rootSize == cpu.rootSize);
          CHECK(back.root == cpu.root);
          if (back.root != cpu.root)
            for (std::size_t i = 0; i < cpu.root.size(); ++i)
              if (back.root[i] != cpu.root[i]) {
                MESSAGE("root word " << i << ": gpu " << std::hex << back.root[i] << " cpu " << cpu.root[i] << " ("
                                     << hybrid::leafDepth(back.root[i]) << " vs " << hybrid::leafDepth(cpu.root[i])
                                     << ")" << std::dec);
                break;
              }
          REQUIRE(back.records.size() == cpu.records.size());
          CHECK(back.records == cpu.records);
          const hybrid::HybridCounts counts = hybrid::countHybrid(cpu);
          for (int k = 1; k <= levels; ++k) CHECK(gpu.recordsAt[std::size_t(k)] == counts.recordsAt[std::size_t(k)]);
          CHECK(gpu.storedBytes() == hybrid::storedBytes(cpu, tech::HybridMapGpu::kRecordRow));
          CHECK(gl::errorCount() == 0);
          ++compared;
          records += int(cpu.records.size());
        }
  MESSAGE(compared << " maps compared, " << records << " records");
  CHECK(records > 1000);  // the cases did exercise the index
}

TEST_CASE("hybrid gpu: an upload reads back as it went in") {
  std::mt19937_64 rng(test::seedFor("hybrid_gpu.upload"));
  const int n = 100;
  const hybrid::HybridMap cpu = hybrid::buildHybrid(shadow::DepthMap(n, n, sceneDepths(rng, n)), cases()[0].rule, 3);
  builder();
  tech::HybridMapGpu gpu;
  tech::HybridBuilder::upload(cpu, gpu);
  const hybrid::HybridMap back = tech::HybridBuilder::download(gpu);
  CHECK(back.root == cpu.root);
  CHECK(back.records == cpu.records);
  CHECK(gpu.storedBytes() == hybrid::storedBytes(cpu, tech::HybridMapGpu::kRecordRow));
}

namespace {

// A probe: for every source texel of the map, the GLSL descent's depth bits, level and steps
// (shaders/07_hybrid_maps/hybrid_descent.glsl), written into an RGBA32UI target of the map's size. The
// shader lives in a scratch shader root next to copies of the includes it tests (the descent
// itself is exercise 07.5's reference, 07_hybrid_maps/exercises_reference.glsl; the preprocessor
// expands both sides of its #ifdef, so the student's file is copied too).
const char* kProbe = R"(#version 410 core
#include "07_hybrid_maps/hybrid_descent.glsl"
uniform usampler2D uRoot, uRecords;
uniform int uLevels;
out uvec4 outProbe;
void main() {
  HybridTexel t = hybridDescend(uRoot, uRecords, uLevels, ivec2(gl_FragCoord.xy));
  outProbe = uvec4(floatBitsToUint(t.depth), uint(t.level), uint(t.steps), 7u);
}
)";

std::vector<std::uint32_t> probe(const tech::HybridMapGpu& map) {
  const fs::path root = fs::temp_directory_path() / "shadowlab_hybrid_probe";
  fs::create_directories(root / "shaders/common");
  fs::create_directories(root / "shaders/07_hybrid_maps");
  for (const char* f : {"07_hybrid_maps/hybrid_descent.glsl", "07_hybrid_maps/hybrid_texel.glsl",
                        "07_hybrid_maps/exercises.glsl", "07_hybrid_maps/exercises_reference.glsl"})
    fs::copy_file(fs::path(configuredSourceRoot()) / "shaders" / f, root / "shaders" / f,
                  fs::copy_options::overwrite_existing);
  fs::copy_file(fs::path(configuredSourceRoot()) / "shaders/common/fullscreen.vert",
                root / "shaders/common/fullscreen.vert", fs::copy_options::overwrite_existing);
  std::ofstream(root / "shaders/probe.frag") << kProbe;
  setenv("SHADOWLAB_ROOT", root.c_str(), 1);
  gl::Program program("hybrid descent probe", {"common/fullscreen.vert", "probe.frag"});
  const bool built = program.build();
  unsetenv("SHADOWLAB_ROOT");
  REQUIRE_MESSAGE(built, program.error());
  const int n = map.sourceSize;
  gl::Texture target = gl::makeTexture(GL_TEXTURE_2D, "probe target");
  glBindTexture(GL_TEXTURE_2D, target.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32UI, n, n, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl::Framebuffer fbo = gl::makeFramebuffer("probe");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
  gl::VertexArray vao = gl::makeVertexArray("probe");
  glViewport(0, 0, n, n);
  glDisable(GL_DEPTH_TEST);
  program.use();
  program.set("uRoot", 0);
  program.set("uRecords", 1);
  program.set("uLevels", map.levels);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, map.root.id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, map.records ? map.records.id() : map.root.id());
  glBindVertexArray(vao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<std::uint32_t> out(std::size_t(n) * std::size_t(n) * 4);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, n, n, GL_RGBA_INTEGER, GL_UNSIGNED_INT, out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, context().framebuffer());
  glActiveTexture(GL_TEXTURE0);
  return out;
}

}  // namespace

TEST_CASE("hybrid gpu: the GLSL descent finds what hybrid::descend finds, for every texel") {
  builder();
  std::mt19937_64 rng(test::seedFor("hybrid_gpu.descent"));
  for (int levels = 0; levels <= hybrid::kMaxLevels; ++levels) {
    const int n = levels == 2 ? 77 : 128;
    const gl::ShadowMap depth = uploadDepth(sceneDepths(rng, n), n, gl::DepthFormat::Depth32F);
    tech::HybridMapGpu gpu;
    builder().build(depth, cases()[0].rule, levels, gpu);
    const hybrid::HybridMap cpu = tech::HybridBuilder::download(gpu);
    const std::vector<std::uint32_t> got = probe(gpu);
    INFO("seed ", test::seed(), " levels ", levels, " size ", n);
    int wrong = 0, deep = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const hybrid::Descent d = hybrid::descend(cpu, x, y);
        const std::uint32_t* p = &got[(std::size_t(y) * std::size_t(n) + std::size_t(x)) * 4];
        wrong += p[0] != hybrid::leafWord(d.depth) || int(p[1]) != d.level || int(p[2]) != d.steps || p[3] != 7u;
        deep += d.steps == levels && levels > 0;
      }
    CHECK(wrong == 0);
    if (levels > 0) CHECK(deep > 0);  // some lookups went all the way down
    CHECK(gl::errorCount() == 0);
  }
}

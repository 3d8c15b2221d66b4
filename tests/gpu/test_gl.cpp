// The GL layer on a real (headless EGL) context: capabilities, error detection, hot reload that
// keeps the last good program, render targets and read-back, timer queries.
#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "app/context.hpp"
#include "app/debug_draw.hpp"
#include "core/mesh.hpp"
#include "gl/caps.hpp"
#include "gl/debug.hpp"
#include "gl/mesh_gpu.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "gl/timer.hpp"

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {
Context& context() {
  static std::unique_ptr<Context> ctx = [] {
    auto c = createHeadlessContext({64, 64, "gpu_tests", true, false});
    gl::installDebugOutput(/*strict=*/true);
    return c;
  }();
  return *ctx;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
  // Make the new write time visible even on coarse file-system clocks.
  fs::last_write_time(p, fs::last_write_time(p) + std::chrono::seconds(1));
}

const char* kVert =
    "#version 410 core\nlayout(location = 0) in vec3 aPosition;\nvoid main() { gl_Position = vec4(aPosition, 1.0); }\n";
const char* kFrag = "#version 410 core\nout vec4 c;\nuniform vec4 uColor;\nvoid main() { c = uColor; }\n";

// kVert and kFrag built from a throwaway shader tree (removed once built).
std::unique_ptr<gl::Program> flatProgram(const std::string& label) {
  const fs::path root = fs::temp_directory_path() / "shadowlab_flat_program";
  write(root / "shaders/t/a.vert", kVert);
  write(root / "shaders/t/a.frag", kFrag);
  setenv("SHADOWLAB_ROOT", root.c_str(), 1);
  auto program = std::make_unique<gl::Program>(label, std::vector<std::string>{"t/a.vert", "t/a.frag"});
  const bool built = program->build();
  unsetenv("SHADOWLAB_ROOT");
  fs::remove_all(root);
  REQUIRE(built);
  return program;
}
}  // namespace

TEST_CASE("gl: the headless context is OpenGL 4.1 core or newer, with a framebuffer") {
  Context& c = context();
  CHECK(gl::caps().atLeast(4, 1));
  CHECK(c.headless());
  CHECK(c.framebuffer() != 0u);
  CHECK(c.width() == 64);
  MESSAGE(c.platform() << ": " << gl::caps().summary());
  // The build without EGL (tests/portability/no_egl.sh) must really run on its hidden window.
  if (const char* platform = std::getenv("SHADOWLAB_EXPECT_PLATFORM")) CHECK(c.platform() == std::string(platform));
  // The gl41 run of this suite (tests/gl41.cmake) must really be macOS's context, or it proves nothing.
  if (const char* gl41 = std::getenv("SHADOWLAB_EXPECT_GL41"); gl41 && std::string(gl41) == "1") {
    const gl::Caps& caps = gl::caps();
    CHECK(caps.major == 4);
    CHECK(caps.minor == 1);
    CHECK(caps.glsl.rfind("4.10", 0) == 0);
    CHECK_FALSE(caps.khrDebug);
    CHECK_FALSE(caps.clipControl);
    CHECK_FALSE(caps.derivativeControl);
    CHECK_FALSE(caps.computeShaders);
    CHECK_FALSE(caps.directStateAccess);
    CHECK_FALSE(caps.parallelShaderCompile);
    CHECK(caps.anisotropic);  // EXT_texture_filter_anisotropic: macOS has it
  }
}

TEST_CASE("gl: a GL error is caught and counted") {
  context();
  const int before = gl::errorCount();
  glEnable(0x1234);  // GL_INVALID_ENUM
  gl::checkErrors("deliberate");
  CHECK(gl::errorCount() == before + 1);
}

// With KHR_debug the driver reports the error at the call; without it (macOS's 4.1, the gl41 run
// of this suite) strict mode polls at both ends of every timed pass, so the error names its pass.
TEST_CASE("gl: a GL error inside a timed pass is caught there and, without KHR_debug, named by the pass") {
  context();
  gl::GpuTimers timers;
  const int before = gl::errorCount();
  {
    gl::TimerScope scope(timers, "deliberate pass");
    glEnable(0x1234);  // GL_INVALID_ENUM
  }
  REQUIRE(gl::errorCount() == before + 1);  // caught when the pass ended, not at the end of a frame
  const std::string message = gl::lastErrorMessage();
  MESSAGE("KHR_debug " << gl::caps().khrDebug << ": " << message);
  if (gl::caps().khrDebug) CHECK(message.find("glEnable") != std::string::npos);
  else CHECK(message == "GL_INVALID_ENUM at the end of pass 'deliberate pass'");
}

TEST_CASE("gl: hot reload keeps the last good program and names file and line of the error") {
  context();
  const fs::path root = fs::temp_directory_path() / "shadowlab_reload_test";
  fs::remove_all(root);
  write(root / "shaders/t/a.vert", kVert);
  write(root / "shaders/t/a.frag", kFrag);
  setenv("SHADOWLAB_ROOT", root.c_str(), 1);
  const int errorsBefore = gl::errorCount();
  {
    gl::Program program("reload test", {"t/a.vert", "t/a.frag"});
    REQUIRE(program.build());
    const GLuint good = program.id();
    CHECK(program.error().empty());

    write(root / "shaders/t/a.frag", "#version 410 core\nout vec4 c;\nvoid main() {\n  c = vec4(1.0) +;\n}\n");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // past the poll interval
    CHECK_FALSE(program.reloadIfChanged());
    CHECK(program.valid());
    CHECK(program.id() == good);  // the last good program is still the one in use
    CHECK(program.error().find((root / "shaders/t/a.frag").string() + ":4:") != std::string::npos);

    write(root / "shaders/t/a.frag", kFrag);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    CHECK(program.reloadIfChanged());
    CHECK(program.error().empty());
  }
  {
    gl::Program missing("missing", {"t/a.vert", "t/none.frag"});
    CHECK_FALSE(missing.build());
    CHECK_FALSE(missing.valid());
    CHECK(missing.error().find("t/none.frag") != std::string::npos);
  }
  unsetenv("SHADOWLAB_ROOT");
  fs::remove_all(root);
  CHECK(gl::errorCount() == errorsBefore);
}

TEST_CASE("gl: render target, a draw, and a top-row-first read-back") {
  context();
  const int errorsBefore = gl::errorCount();
  const auto flat = flatProgram("draw test");
  const gl::Program& program = *flat;

  gl::RenderTarget rt = gl::makeRenderTarget(8, 8, "test target");
  glBindFramebuffer(GL_FRAMEBUFFER, rt.fbo.id());
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // A triangle covering the top half of the viewport (y > 0 in NDC).
  Mesh tri;
  tri.positions = {{-1, 0, 0}, {3, 0, 0}, {-1, 3, 0}};
  tri.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  tri.uvs = {{0, 0}, {0, 0}, {0, 0}};
  tri.indices = {0, 1, 2};
  gl::GpuMesh mesh = gl::uploadMesh(tri, "test triangle");
  program.use();
  program.set("uColor", glm::vec4(1, 0, 0, 1));
  glDisable(GL_DEPTH_TEST);
  mesh.draw();
  const Image8 img = gl::readPixels(rt.fbo.id(), 8, 8);
  CHECK(img.at(4, 0)[0] == 255);  // top row: red triangle
  CHECK(img.at(4, 0)[2] == 0);
  CHECK(img.at(4, 7)[0] == 0);  // bottom row: blue clear colour
  CHECK(img.at(4, 7)[2] == 255);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  CHECK(gl::errorCount() == errorsBefore);
}

TEST_CASE("gl: a mesh drawn in its view order meets the depth test nearest first") {
  context();
  const int errorsBefore = gl::errorCount();
  const auto flat = flatProgram("view order test");
  const gl::Program& program = *flat;
  // Eight quads over the whole viewport at NDC depths -0.7 .. 0.7, in a shuffled order: the vertex
  // shader passes positions through, so the mesh's space is NDC and depth LESS keeps small z.
  Mesh stack;
  for (int k = 0; k < 8; ++k) {
    const float z = -0.7f + 0.2f * float((k * 3 + 5) % 8);
    const auto base = std::uint32_t(stack.positions.size());
    stack.positions.insert(stack.positions.end(), {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}});
    stack.normals.insert(stack.normals.end(), 4, glm::vec3(0, 0, 1));
    stack.uvs.insert(stack.uvs.end(), 4, glm::vec2(0));
    stack.indices.insert(stack.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  const gl::GpuMesh sorted = gl::uploadMesh(stack, "stack with view orders", true);
  const gl::GpuMesh plain = gl::uploadMesh(stack, "stack");
  CHECK(sorted.viewOrders);
  CHECK(plain.orderFor(glm::mat4(1.0f), {0, 0, -1, 0}) == -1);
  gl::RenderTarget rt = gl::makeRenderTarget(8, 8, "view order target");
  glBindFramebuffer(GL_FRAMEBUFFER, rt.fbo.id());
  glViewport(0, 0, 8, 8);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  program.use();
  program.set("uColor", glm::vec4(1, 0, 0, 1));
  GLuint query = 0;
  glGenQueries(1, &query);
  auto samplesPassed = [&](const gl::GpuMesh& mesh, int order) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    mesh.draw(order);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    return samples;
  };
  // A viewer on the -z side (toward it: -z) sees small z nearest: one layer passes, 64 samples; one
  // on the +z side gets the far-to-near order of that viewer's opposite, every layer passing.
  const int nearFirst = sorted.orderFor(glm::mat4(1.0f), {0, 0, -1, 0});
  const int farFirst = sorted.orderFor(glm::mat4(1.0f), {0, 0, 1, 0});
  CHECK(samplesPassed(sorted, nearFirst) == 64u);
  CHECK(samplesPassed(sorted, farFirst) == 8u * 64u);
  const GLuint own = samplesPassed(sorted, -1);  // the shuffled order: in between
  CHECK(own > 64u);
  CHECK(own < 8u * 64u);
  CHECK(samplesPassed(plain, nearFirst) == own);  // a mesh without orders ignores the order
  // The same through a model matrix and a viewer point: turned half round about y, the stack's +z
  // faces -z, and an eye at z = -5 sees its +z side nearest.
  const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), glm::vec3(0, 1, 0));
  CHECK(sorted.orderFor(turned, {0, 0, -5, 1}) == farFirst);
  glDeleteQueries(1, &query);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  CHECK(gl::errorCount() == errorsBefore);
}

TEST_CASE("gl: timer queries resolve without stalling, per named pass") {
  glBindFramebuffer(GL_FRAMEBUFFER, context().framebuffer());
  gl::GpuTimers timers;
  for (int frame = 0; frame < 3; ++frame) {
    {
      gl::TimerScope a(timers, "clear");
      glClear(GL_COLOR_BUFFER_BIT);
    }
    timers.collect();
  }
  glFinish();
  timers.collect();
  REQUIRE(timers.find("clear"));
  CHECK(timers.find("clear")->samples == 3);
  CHECK(timers.find("clear")->gpuMs >= 0.0);
  CHECK_THROWS_AS(timers.end(), std::logic_error);
}

TEST_CASE("gl: a pass not begun in this frame is not drawn; passes inside a switched-off stretch are not timed") {
  glBindFramebuffer(GL_FRAMEBUFFER, context().framebuffer());
  gl::GpuTimers timers;
  timers.setFrame(1);
  {
    gl::TimerScope a(timers, "shadow");  // drawn in frame 1 only (its map kept afterwards)
    glClear(GL_COLOR_BUFFER_BIT);
  }
  {
    gl::TimerScope b(timers, "scene");
    glClear(GL_COLOR_BUFFER_BIT);
  }
  REQUIRE(timers.find("shadow"));
  CHECK(timers.find("shadow")->drawn);
  CHECK(timers.find("scene")->drawn);
  timers.setFrame(2);
  CHECK_FALSE(timers.find("shadow")->drawn);
  CHECK_FALSE(timers.find("scene")->drawn);
  {
    gl::TimerScope b(timers, "scene");
    glClear(GL_COLOR_BUFFER_BIT);
  }
  CHECK_FALSE(timers.find("shadow")->drawn);  // the header shows it as skipped
  CHECK(timers.find("scene")->drawn);
  timers.setFrame(2);  // the same frame again (a second render of it): nothing cleared
  CHECK(timers.find("scene")->drawn);

  // Lesson 10's four-up quarter: one pass open, the timers off inside it, the open one still ends.
  timers.setFrame(3);
  timers.begin("quarter 0: uniform");
  timers.setEnabled(false);
  CHECK_FALSE(timers.enabled());
  {
    gl::TimerScope inner(timers, "shadow light0");  // a no-op: no "begun inside" error
    glClear(GL_COLOR_BUFFER_BIT);
  }
  timers.setEnabled(true);
  CHECK_NOTHROW(timers.end());
  glFinish();
  timers.collect();
  REQUIRE(timers.find("quarter 0: uniform"));
  CHECK(timers.find("quarter 0: uniform")->samples == 1);
  CHECK(timers.find("quarter 0: uniform")->drawn);
  CHECK(timers.find("shadow light0") == nullptr);
  CHECK_FALSE(timers.find("shadow")->drawn);
}

TEST_CASE("gl: sizes past the GL limits are errors naming the limit, never a black texture or a huge frame") {
  context();
  const gl::Caps& caps = gl::caps();
  MESSAGE("GL_MAX_TEXTURE_SIZE " << caps.maxTextureSize << ", GL_MAX_RENDERBUFFER_SIZE " << caps.maxRenderbufferSize
                                 << ", GL_MAX_VIEWPORT_DIMS " << caps.maxViewport[0] << "x" << caps.maxViewport[1]);
  REQUIRE(caps.maxTextureSize >= 1024);  // the GL 4.1 minimum is 16384; llvmpipe reports its own
  CHECK(gl::textureSizeProblem(caps.maxTextureSize, 1).empty());
  CHECK(gl::textureSizeProblem(1, caps.maxTextureSize + 1).find("GL_MAX_TEXTURE_SIZE") != std::string::npos);
  CHECK(gl::framebufferSizeProblem(640, 360).empty());
  CHECK(gl::framebufferSizeProblem(caps.maxViewport[0] + 1, 16).find("exceeds this OpenGL's limits") !=
        std::string::npos);

  Image8 wide;  // one row past the limit: glTexImage2D would fail and the texture sample black
  wide.width = caps.maxTextureSize + 1;
  wide.height = 1;
  wide.channels = 4;
  wide.data.assign(std::size_t(wide.width) * 4, 255);
  const int errors = gl::errorCount();
  try {
    gl::uploadTexture(wide, "too wide");
    FAIL("a texture past GL_MAX_TEXTURE_SIZE uploaded");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "texture 'too wide': " + std::to_string(wide.width) +
                                       "x1 is larger than this OpenGL's GL_MAX_TEXTURE_SIZE " +
                                       std::to_string(caps.maxTextureSize) + " (" + caps.renderer + ")");
  }
  CHECK(gl::errorCount() == errors);  // refused before GL saw it
}

namespace {
// Rows of column x (of a w x h read-back) whose red channel is lit.
int litRows(const Image8& img, int x) {
  int n = 0;
  for (int y = 0; y < img.height; ++y) n += img.at(x, y)[0] > 128 ? 1 : 0;
  return n;
}
}  // namespace

TEST_CASE("gl: debug lines are as wide as asked (projector scale), and one behind the camera does not flip") {
  context();
  const int errorsBefore = gl::errorCount();
  gl::RenderTarget rt = gl::makeRenderTarget(64, 64, "line test");
  glBindFramebuffer(GL_FRAMEBUFFER, rt.fbo.id());
  glViewport(0, 0, 64, 64);
  LineRenderer lines("line test");
  const std::vector<DebugDraw::Line> across = {{{-0.5f, 0, 0}, {0.5f, 0, 0}, {1, 0, 0, 1}}};
  for (float width : {4.0f, 8.0f}) {
    CAPTURE(width);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    lines.draw(across, glm::mat4(1), false, width);
    const Image8 img = gl::readPixels(rt.fbo.id(), 64, 64);
    CHECK(litRows(img, 32) == int(width));
    CHECK(litRows(img, 4) == 0);  // the ends stop half a width past the segment (x = +-0.5)
  }
  CHECK(LineRenderer::projectorWidth(720) == doctest::Approx(2.5));
  CHECK(LineRenderer::projectorWidth(1440) == doctest::Approx(5.0));
  CHECK(LineRenderer::projectorWidth(180) == doctest::Approx(2.0));  // never thinner than 2 pixels

  // From a point in front of a perspective camera to one behind it: only the part in front is drawn,
  // on the side of the screen where the front point lies (divided by a negative w, the far end
  // would land on the other side).
  const glm::mat4 viewProj = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  const std::vector<DebugDraw::Line> behind = {{{0.5f, 0, -2}, {0.5f, 0, 5}, {1, 0, 0, 1}}};
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lines.draw(behind, viewProj, false, 4.0f);
  const Image8 img = gl::readPixels(rt.fbo.id(), 64, 64);
  int left = 0, right = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) (x < 32 ? left : right) += img.at(x, y)[0] > 128 ? 1 : 0;
  CHECK(right > 0);
  CHECK(left == 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  CHECK(gl::errorCount() == errorsBefore);
}

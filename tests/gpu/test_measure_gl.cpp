// The measurement path end to end on a real context: a shader writes a texel mapping whose
// Jacobian is known in closed form, the framework reads back its screen-space derivatives, and the
// aliasing statistics must come out as the formula says; the ground truth sees an unoccluded plane.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/context.hpp"
#include "app/measurement.hpp"
#include "core/mesh_gen.hpp"
#include "core/paths.hpp"
#include "gl/debug.hpp"
#include "gl/gl.hpp"

using namespace shadowlab;
namespace fs = std::filesystem;

TEST_CASE("measure (GPU): m from shader derivatives matches a texel mapping known in closed form") {
  static auto ctx = createHeadlessContext({96, 64, "measure test", true, false});
  gl::installDebugOutput();
  const int errorsBefore = gl::errorCount();

  // A shader tree with the course's common shaders and a test pair: a full-screen triangle whose
  // "shadow texel" coordinates are texel = (0.5 x, 0.25 y) in window pixels: J = diag(0.5, 0.25),
  // sigma_min = 0.25, so every pixel has m = 1 / 0.25 = 4.
  const fs::path root = fs::temp_directory_path() / "shadowlab_measure_gl_test";
  fs::remove_all(root);
  fs::create_directories(root / "shaders/t");
  fs::copy(fs::path(configuredSourceRoot()) / "shaders/common", root / "shaders/common", fs::copy_options::recursive);
  std::ofstream(root / "shaders/t/quad.vert") << "#version 410 core\nout vec2 vUv;\nvoid main() {\n"
                                                 "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n  vUv = "
                                                 "p;\n  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n";
  std::ofstream(root / "shaders/t/quad.frag")
      << "#version 410 core\n#include \"common/measure.glsl\"\nin vec2 vUv;\n"
         "out vec4 fragColor;\nvoid main() {\n  fragColor = vec4(vUv, 0.0, 1.0);\n"
         "  writeMeasurement(vec3(vUv.x * 10.0, 0.0, vUv.y * 10.0), vec3(0.0, 1.0, 0.0), 1.0, gl_FragCoord.xy * "
         "vec2(0.5, 0.25));\n}\n";
  setenv("SHADOWLAB_ROOT", root.c_str(), 1);
  {
    gl::Program quad("measure test quad", {"t/quad.vert", "t/quad.frag"});
    REQUIRE(quad.build());
    ParamRegistry params;
    Measurement measurement;
    measurement.declare(params);
    params.set("measure.overlay", "aliasing");
    params.set("measure.scale", "1");

    // The plane the shader pretends to shade, and a sun straight above: nothing occludes it.
    Scene scene;
    scene.addMaterial({});
    scene.addObject({"plane", scene.addMesh(makePlane(40.0f, 4)), 0, glm::mat4(1.0f)});
    Light sun;
    sun.kind = LightKind::Directional;
    sun.direction = {0, -1, 0};

    const unsigned frame = ctx->framebuffer();
    FrameInfo info;
    info.width = ctx->width();
    info.height = ctx->height();
    const unsigned target = measurement.begin(frame, info);
    CHECK(target != frame);  // measuring renders into the framework's attachments
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, ctx->width(), ctx->height());
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    quad.use();
    gl::VertexArray vao = gl::makeVertexArray("measure test");
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    measurement.end({&scene, 1, {sun}}, frame, true);

    const MeasureResult& r = measurement.result();
    REQUIRE(r.valid);
    CHECK(r.width == 96);
    CHECK(r.hard.facingPixels == 96u * 64u);
    CHECK(r.hard.misclassified == 0u);  // V = 1 everywhere, and the plane is lit everywhere
    REQUIRE(r.hasAliasing);
    CHECK(r.aliasing.pixels == 96u * 64u);
    CHECK(r.aliasing.mean == doctest::Approx(4.0));
    CHECK(r.aliasing.max == doctest::Approx(4.0));
    CHECK(r.aliasing.shareAbove1 == doctest::Approx(1.0));
  }
  unsetenv("SHADOWLAB_ROOT");
  fs::remove_all(root);
  CHECK(gl::errorCount() == errorsBefore);
}

// Public GLSL cases for lesson 06: exercises 06.8 (ripLevelOfDetail) and 06.9 (ripBilinear) in
// shaders/06_texture_filtering/exercises.glsl. Each case evaluates GLSL on the GPU
// (app/glsl_cases.hpp) against a procedural 8x4 RIP map the prelude defines; expected values are
// worked out by hand, or (random cases) the reference GLSL's. The renders compare the whole
// lesson, sampling=rip_map, with your shader against the reference (tests/grading/glsl_grader.cpp).
#include <random>

#include "app/glsl_cases.hpp"
#include "grading/cases.hpp"

namespace {
using shadowlab::GlslCase;
using shadowlab::glslVec;

// What the lesson's scene.frag provides to the exercises, here for a procedural 8x4 map whose
// texel t of level (lu, lv) is (t.x / 8, t.y / 4, lu / 4 + lv / 16, ((7 t.x + 3 t.y) mod 5) / 4).
const char* const kPrelude = R"(
ivec2 ripLevelSize(ivec2 level) { return max(ivec2(8, 4) >> level, ivec2(1)); }
vec4 ripTexel(ivec2 level, ivec2 t) {
  ivec2 size = ripLevelSize(level);
  t -= size * ivec2(floor(vec2(t) / vec2(size)));
  return vec4(float(t.x) / 8.0, float(t.y) / 4.0, float(level.x) / 4.0 + float(level.y) / 16.0,
              float((t.x * 7 + t.y * 3) % 5) / 4.0);
}
)";
const char* const kMap =
    "the procedural 8x4 RIP map: texel t of level (lu, lv) = (t.x/8, t.y/4, lu/4 + lv/16, ((7 t.x + 3 t.y) mod 5)/4)";

shadowlab::GlslExerciseSet ex06() {
  shadowlab::GlslExerciseSet set;
  set.ids = {"06.8", "06.9"};
  set.source = "tests/grading/glsl/ex06_glsl.cpp";
  set.prelude = kPrelude;
  set.cases = {
      {"ex06.8: one texel per pixel along u is level 0, four along v level 2",
       "vec4(ripLevelOfDetail(vec2(1.0 / 256.0, 0.0), vec2(0.0, 4.0 / 256.0), ivec2(256, 256)), 0, 0)",
       glm::vec4(0, 2, 0, 0), 1e-4f, 2},
      {"ex06.8: each axis takes the larger of its two derivatives",
       "vec4(ripLevelOfDetail(vec2(2.0 / 64.0, 8.0 / 32.0), vec2(4.0 / 64.0, 1.0 / 32.0), ivec2(64, 32)), 0, 0)",
       glm::vec4(2, 3, 0, 0), 1e-4f, 2, "u: max(2, 4) texels -> 2; v: max(8, 1) texels -> 3"},
      {"ex06.8: magnification is negative; the derivatives' signs do not matter",
       "vec4(ripLevelOfDetail(vec2(-0.25 / 16.0, 0.0), vec2(0.0, -0.5 / 16.0), ivec2(16, 16)), 0, 0)",
       glm::vec4(-2, -1, 0, 0), 1e-4f, 2},
      {"ex06.9: at a texel centre, exactly that texel", "ripBilinear(ivec2(0, 0), vec2(2.5 / 8.0, 1.5 / 4.0))",
       glm::vec4(0.25f, 0.25f, 0, 0.5f), 1e-5f, 4, std::string(kMap) + "; texel (2, 1)"},
      {"ex06.9: halfway between two texels along u", "ripBilinear(ivec2(0, 0), vec2(3.0 / 8.0, 1.5 / 4.0))",
       glm::vec4(0.3125f, 0.25f, 0, 0.75f), 1e-5f, 4, std::string(kMap) + "; the mean of texels (2, 1) and (3, 1)"},
      {"ex06.9: wraps at u = 0 (REPEAT)", "ripBilinear(ivec2(0, 0), vec2(0.0, 1.5 / 4.0))",
       glm::vec4(0.4375f, 0.25f, 0, 0.625f), 1e-5f, 4, std::string(kMap) + "; the mean of texels (7, 1) and (0, 1)"},
      {"ex06.9: a level one texel high along v", "ripBilinear(ivec2(0, 2), vec2(2.5 / 8.0, 0.7))",
       glm::vec4(0.25f, 0, 0.125f, 1), 1e-5f, 4, std::string(kMap) + "; level (0, 2) is 8x1: texel (2, 0)"},
  };
  std::mt19937_64 rng(shadowlab::grading::seedFor("ex06 GLSL"));
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < 12; ++i) {
    const glm::vec2 dx(0.05f * u(rng), 0.05f * u(rng)), dy(0.05f * u(rng), 0.05f * u(rng));
    set.cases.push_back({"ex06.8: random derivatives " + std::to_string(i),
                         "vec4(ripLevelOfDetail(" + glslVec(dx) + ", " + glslVec(dy) + ", ivec2(" +
                             std::to_string(64 << (i % 3)) + ", " + std::to_string(32 << (i % 4)) + ")), 0, 0)",
                         std::nullopt, 1e-4f, 2});
  }
  for (int i = 0; i < 12; ++i) {
    const glm::vec2 uv(2.5f * u(rng) + 0.5f, 2.5f * u(rng) + 0.5f);
    const std::string level = "ivec2(" + std::to_string(i % 4) + ", " + std::to_string((i / 4) % 3) + ")";
    set.cases.push_back({"ex06.9: random coordinates " + std::to_string(i),
                         "ripBilinear(" + level + ", " + glslVec(uv) + ")", std::nullopt, 1e-5f, 4, kMap});
  }
  set.renders = {
      {"ex06.9: the RIP-map preset (rip_vs_mip)", {"--preset", "rip_vs_mip"}},
      {"ex06.9: RIP maps with a LOD bias of 1.5 on the tunnel",
       {"--preset", "rip_vs_mip", "--set", "filter.lod_bias=1.5", "--set", "scene=tunnel"}},
  };
  return set;
}

const bool registered = (shadowlab::registerGlslExercises("06_texture_filtering", ex06), true);
}  // namespace

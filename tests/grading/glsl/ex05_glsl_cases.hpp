#pragma once
// Lesson 05's GLSL cases, shared by the public (glsl/ex05_glsl.cpp) and hidden
// (hidden/ex05_glsl_hidden.cpp) ones: what the technique gives blockerSearch to call (eight search
// taps, two analytic depth maps) and the random searches.
#include <random>
#include <string>

#include "app/glsl_cases.hpp"

namespace shadowlab::ex05glsl {

// The maps are functions, not textures, so no tap sits on a texel edge that rounding could move it
// across: light 0 is a step (a blocker at distance 4 over u < 0.5, the floor at 10 beyond), light 1
// a ramp 3 + 4u + 2v. The taps are no rotation's fixed points (a wrong turn moves them).
inline const char* const kPrelude = R"(
#define SEARCH_TAPS 8
const vec2 uSearchTaps[SEARCH_TAPS] = vec2[](vec2(0.9, 0.1), vec2(-0.3, 0.8), vec2(-0.7, -0.4), vec2(0.2, -0.9),
                                             vec2(0.4, 0.3), vec2(-0.5, 0.1), vec2(0.1, -0.35), vec2(0.6, -0.5));
float softDepthAt(int light, int k, vec2 uv) {
  if (light == 0) return uv.x < 0.5 ? 4.0 : 10.0;
  return 3.0 + 4.0 * uv.x + 2.0 * uv.y;
}
)";
inline const char* const kMaps =
    "taps (0.9, 0.1) (-0.3, 0.8) (-0.7, -0.4) (0.2, -0.9) (0.4, 0.3) (-0.5, 0.1) (0.1, -0.35) (0.6, -0.5); "
    "light 0: distance 4 where u < 0.5, else 10; light 1: 3 + 4u + 2v";

// The technique's per-pixel turn by `angle` (shadow_pcss.frag builds it the same way).
inline std::string turn(float angle) {
  const std::string a = glslFloat(angle);
  return "mat2(cos(" + a + "), sin(" + a + "), -sin(" + a + "), cos(" + a + "))";
}

// A random search on the ramp (the mean and the count), then one whose every tap is a blocker
// (light 0 well inside u < 0.5: (4, 8)), which the stub's vec2(0.0) fails.
inline GlslCase randomSearches(std::mt19937_64& rng, const std::string& name) {
  std::uniform_real_distribution<float> u(0, 1);
  const glm::vec2 uv(0.2f + 0.6f * u(rng), 0.2f + 0.6f * u(rng));
  const float z = 4.0f + 4.0f * u(rng), bias = 0.05f * u(rng), radius = 0.02f + 0.2f * u(rng);
  const glm::vec2 plane(8 * u(rng) - 4, 8 * u(rng) - 4);
  const glm::vec2 inside(0.1f + 0.2f * u(rng), u(rng));
  const std::string e = "vec4(blockerSearch(1, " + glslVec(uv) + ", " + glslFloat(z) + ", " + glslVec(plane) + ", " +
                        glslFloat(bias) + ", " + glslFloat(radius) + ", " + turn(6.2832f * u(rng)) +
                        "), blockerSearch(0, " + glslVec(inside) + ", 10.0, vec2(0.0), 0.01, 0.08, " +
                        turn(6.2832f * u(rng)) + "))";
  return {name + " (seed " + std::to_string(grading::seed()) + ")", e, std::nullopt, 1e-4f, 4, kMaps};
}

}  // namespace shadowlab::ex05glsl

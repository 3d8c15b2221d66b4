#pragma once
// Lesson 03's GLSL cases, shared by the public (glsl/ex03_glsl.cpp) and hidden
// (hidden/ex03_glsl_hidden.cpp) ones: what the technique gives pcfKernel to call, the two depth
// maps, and the random kernels (each tap robust to rounding: see ex03_glsl.cpp).
#include <random>
#include <string>
#include <vector>

#include "app/glsl_cases.hpp"

namespace shadowlab::ex03glsl {

// tap2D as shadow_uniform.frag has it, on R32F maps: GL_LEQUAL against the nearest texel.
inline const char* const kPrelude = R"(
uniform sampler2D uCaseMap, uCaseMap2;  // light 0's and light 1's maps, 8x8 each
float tap2D(int map, vec3 p) {
  float stored = map == 0 ? textureLod(uCaseMap, p.xy, 0.0).r : textureLod(uCaseMap2, p.xy, 0.0).r;
  return p.z <= stored ? 1.0 : 0.0;
}
)";
inline const char* const kEdgeMap = "map 0: 8x8, columns 0-3 store 0.2, columns 4-7 store 0.8";
inline const char* const kPatternMap = "map 1: 8x8, texel (x, y) stores ((3x + 5y) mod 11) / 10";

inline std::vector<GlslFixture> fixtures() {
  GlslFixture edge{"uCaseMap", 8, 8, {}}, pattern{"uCaseMap2", 8, 8, {}};
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      edge.values.push_back(x < 4 ? 0.2f : 0.8f);
      pattern.values.push_back(float((3 * x + 5 * y) % 11) / 10.0f);
    }
  return {edge, pattern};
}

// One kernel on a random map, texel, odd n up to maxN, depth and receiver slope: taps 0.2..0.8 of
// a texel from its edges, tap depths 0.005 + k 0.01 against stored multiples of 0.01.
inline std::string randomKernel(std::mt19937_64& rng, int maxN) {
  std::uniform_int_distribution<int> texel(0, 7), step(0, 99), slope(-5, 5), half(0, maxN / 2), map(0, 1);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  const glm::vec2 uv((float(texel(rng)) + 0.5f + jitter(rng)) / 8, (float(texel(rng)) + 0.5f + jitter(rng)) / 8);
  const float depth = 0.005f + 0.01f * float(step(rng));
  const glm::vec2 dzduv(0.08f * float(slope(rng)), 0.08f * float(slope(rng)));  // 0.01 per texel offset
  return "pcfKernel(" + std::to_string(map(rng)) + ", " + glslVec(uv) + ", " + glslFloat(depth) + ", " +
         glslVec(dzduv) + ", 0.125, " + std::to_string(2 * half(rng) + 1) + ")";
}

// Three random kernels, then one certainly shadowed (map 0, columns 0-2 deep in the 0.2 half,
// depth 0.505): the reference GLSL's values; the always-lit stub fails the last.
inline GlslCase randomKernels(std::mt19937_64& rng, const std::string& name, int maxN = 7) {
  std::uniform_int_distribution<int> column(0, 1), row(0, 7);
  std::string e = "vec4(";
  for (int k = 0; k < 3; ++k) e += randomKernel(rng, maxN) + ", ";
  const glm::vec2 uv((float(column(rng)) + 0.5f) / 8, (float(row(rng)) + 0.5f) / 8);
  e += "pcfKernel(0, " + glslVec(uv) + ", 0.505, vec2(0.0), 0.125, 3))";
  return {name + " (seed " + std::to_string(grading::seed()) + ")",
          e,
          std::nullopt,
          1e-5f,
          4,
          std::string(kEdgeMap) + "; " + kPatternMap};
}

}  // namespace shadowlab::ex03glsl

#pragma once
// Lesson 07's GLSL cases, shared by the public (glsl/ex07_glsl.cpp) and hidden
// (hidden/ex07_glsl_hidden.cpp) ones: two small hybrid maps over one records texture, the
// prelude that reads a descent as (depth, level, steps), and the random descents.
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "app/glsl_cases.hpp"

namespace shadowlab::ex07glsl {

// hybridDescend is declared ahead of the exercise file, which defines it (after this prelude).
inline const char* const kPrelude = R"(
#include "07_hybrid_maps/hybrid_texel.glsl"
uniform usampler2D uCaseRoot2, uCaseRoot3, uCaseRecords;
HybridTexel hybridDescend(usampler2D root, usampler2D records, int levels, ivec2 s);
// Map A: 8x8 source texels, 2 levels (root 2x2); map B: 8x8, 3 levels (root 1x1).
vec4 descentA(ivec2 s) {
  HybridTexel t = hybridDescend(uCaseRoot2, uCaseRecords, 2, s);
  return vec4(t.depth, float(t.level), float(t.steps), 0.0);
}
vec4 descentB(ivec2 s) {
  HybridTexel t = hybridDescend(uCaseRoot3, uCaseRecords, 3, s);
  return vec4(t.depth, float(t.level), float(t.steps), 0.0);
}
)";
// What a failure prints before the case's own path (the maps are drawn out in fixtures() below).
inline const char* const kMaps =
    "compared: (depth, level, steps); map A: 2 levels, root 2x2; map B: 3 levels, root 1x1 (fixtures in "
    "tests/grading/glsl/ex07_glsl_cases.hpp); record r at texel (r & 1023, r >> 10); children (0,0) (1,0) (0,1) (1,1)";

inline std::uint32_t leaf(float depth) {
  std::uint32_t w;
  std::memcpy(&w, &depth, sizeof w);
  return w;
}
inline std::uint32_t pointer(std::uint32_t record) { return 0x80000000u | record; }

inline std::vector<GlslFixture> fixtures() {
  GlslFixture rootA{"uCaseRoot2", 2, 2, {}, {leaf(0.25f), pointer(0), pointer(1025), leaf(0.375f)}, 1};
  GlslFixture rootB{"uCaseRoot3", 1, 1, {}, {pointer(4)}, 1};
  GlslFixture records{"uCaseRecords", 1024, 2, {}, std::vector<std::uint32_t>(1024 * 2 * 4, leaf(0.99f)), 4};
  auto put = [&](std::uint32_t r, std::vector<std::uint32_t> words) {
    for (std::size_t i = 0; i < 4; ++i) records.words[4 * r + i] = words[i];  // row r >> 10, column r & 1023
  };
  put(0, {leaf(0.5f), pointer(1), leaf(0.75f), leaf(0.125f)});
  put(1, {leaf(0.1f), leaf(0.2f), leaf(0.3f), leaf(0.4f)});
  put(1025, {leaf(0.6f), leaf(0.65f), leaf(0.7f), pointer(3)});
  put(3, {leaf(0.9f), leaf(0.8f), leaf(0.7f), leaf(0.05f)});
  put(4, {pointer(5), leaf(0.33f), leaf(0.44f), leaf(0.55f)});
  put(5, {leaf(0.15f), pointer(6), leaf(0.35f), leaf(0.45f)});
  put(6, {leaf(0.61f), leaf(0.62f), leaf(0.63f), leaf(0.64f)});
  return {rootA, rootB, records};
}

// One descent of map A or B at a random source texel: the reference GLSL's value. Every leaf
// stores a depth below 1, so the stub's 1.0 fails every one.
inline GlslCase randomDescent(std::mt19937_64& rng, const std::string& name) {
  std::uniform_int_distribution<int> texel(0, 7), map(0, 1);
  const bool b = map(rng) == 1;
  const std::string s = "ivec2(" + std::to_string(texel(rng)) + ", " + std::to_string(texel(rng)) + ")";
  return {name + " (seed " + std::to_string(grading::seed()) + ")",
          std::string(b ? "descentB(" : "descentA(") + s + ")",
          std::nullopt,
          0.0f,
          3,
          kMaps};
}

}  // namespace shadowlab::ex07glsl

#pragma once
// Lesson 08's GLSL cases, shared by the public (glsl/ex08_glsl.cpp) and hidden
// (hidden/ex08_glsl_hidden.cpp) ones: GLSL literals of matrices, and the random lookups (each well
// away from w = 0 and from w = 1, where forgetting the divide would not show: see ex08_glsl.cpp).
#include <cmath>
#include <random>
#include <string>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"

namespace shadowlab::ex08glsl {

// A GLSL mat4 literal, column by column as GLSL and GLM store it.
inline std::string glslMat(const glm::mat4& m) {
  std::string s = "mat4(";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) s += (c || r ? ", " : "") + glslFloat(m[c][r]);
  return s + ")";
}

// A random matrix (entries in [-1, 1]) and a random world point (in [-2, 2]^3) whose clip w lies
// in +-[0.5, 0.75] or +-[1.25, 2] (front = true: positive) and whose divided coordinates stay
// within 4: the map coordinates are then below 2.5 and the divide moves them by at least 1/8 of h.
inline std::pair<glm::mat4, glm::vec3> randomLookup(std::mt19937_64& rng, bool front) {
  std::uniform_real_distribution<float> entry(-1, 1), coord(-2, 2);
  for (;;) {
    glm::mat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = entry(rng);
    const glm::vec3 p(coord(rng), coord(rng), coord(rng));
    const glm::vec4 h = m * glm::vec4(p, 1);
    const float w = front ? h.w : -h.w, ndc = glm::max(glm::abs(h.x), glm::max(glm::abs(h.y), glm::abs(h.z))) / w;
    if (w >= 0.5f && w <= 2.0f && (w <= 0.75f || w >= 1.25f) && ndc <= 4.0f) return {m, p};
  }
}

// x, y, z: a point the map knows (its window coordinates); w: whether it knows a second point of
// the same matrix, in front or behind at random. The reference GLSL's values; the stub's vec4(0)
// fails the first three.
inline GlslCase randomLookups(std::mt19937_64& rng, const std::string& name) {
  const auto [m, p] = randomLookup(rng, true);
  const float lowestW = m[3][3] - 2 * (std::abs(m[0][3]) + std::abs(m[1][3]) + std::abs(m[2][3]));
  const bool front = std::uniform_int_distribution<int>(0, 1)(rng) == 1 || lowestW > -0.6f;  // behind: if any
  std::uniform_real_distribution<float> coord(-2, 2);
  glm::vec3 q;
  do q = glm::vec3(coord(rng), coord(rng), coord(rng));  // well on the chosen side of w = 0
  while (!(front ? (m * glm::vec4(q, 1)).w >= 0.5f : (m * glm::vec4(q, 1)).w <= -0.5f));
  const std::string M = glslMat(m);
  return {name + " (seed " + std::to_string(grading::seed()) + ")",
          "vec4(psmMapCoords(" + M + ", vec3(" + glslFloat(p.x) + ", " + glslFloat(p.y) + ", " + glslFloat(p.z) +
              ")).xyz, psmMapCoords(" + M + ", vec3(" + glslFloat(q.x) + ", " + glslFloat(q.y) + ", " + glslFloat(q.z) +
              ")).w)",
          std::nullopt,
          1e-4f,
          4,
          "x y z: the first point's (u, v, depth); w: 1 if the map knows the second point, else 0"};
}

}  // namespace shadowlab::ex08glsl

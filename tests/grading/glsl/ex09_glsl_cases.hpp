#pragma once
// Lesson 09's GLSL cases, shared by the public (glsl/ex09_glsl.cpp) and hidden
// (hidden/ex09_glsl_hidden.cpp) ones: random face choices, each far from a tie (see ex09_glsl.cpp).
#include <algorithm>
#include <array>
#include <random>
#include <string>

#include <glm/glm.hpp>

#include "algorithms/psm/cube_faces.hpp"
#include "app/glsl_cases.hpp"

namespace shadowlab::ex09glsl {

struct FaceCall {
  glm::vec3 q{0};
  glm::vec4 light{0};
  std::array<int, 6> layers{};
  int layer = -1;  // what the call returns (cubeFaceOf's), to keep the calls away from ties
};

inline std::string glsl(const FaceCall& c) {
  std::string layers = "int[6](";
  for (int f = 0; f < 6; ++f) layers += (f ? ", " : "") + std::to_string(c.layers[std::size_t(f)]);
  return "cubeFaceLayer(vec3(" + glslFloat(c.q.x) + ", " + glslFloat(c.q.y) + ", " + glslFloat(c.q.z) + "), " +
         glslVec(c.light) + ", " + layers + "))";
}

// The layer a call returns, by the library's cubeFaceOf (algorithms/psm/cube_faces.hpp: the
// faces with a map as the hidden set).
inline int layerOf(const glm::dvec3& q, const glm::dvec4& light, const std::array<int, 6>& layers) {
  psm::PostProjectiveLight post;  // a point light's kind (in front, behind) does not matter here
  if (light.w == 0) {
    post.kind = psm::PostLightKind::Direction;
    post.direction = glm::normalize(glm::dvec3(light));
  } else post.position = glm::dvec3(light);
  unsigned mask = 0;
  for (int f = 0; f < 6; ++f)
    if (layers[std::size_t(f)] >= 0) mask |= 1u << f;
  const int f = psm::cubeFaceOf(q, post, mask);
  return f < 0 ? -1 : layers[std::size_t(f)];
}

// The call's answer, or false when it is near a tie: moving the point or the light by 1e-3 along
// any axis (ten thousand times float's rounding) changes it, or the point is within 0.2 of a
// point light.
inline bool decide(FaceCall& c) {
  const glm::dvec3 q(c.q);
  const glm::dvec4 light(c.light);
  if (light.w != 0 && glm::length(q - glm::dvec3(light)) < 0.2) return false;
  c.layer = layerOf(q, light, c.layers);
  for (int axis = 0; axis < 3; ++axis)
    for (double step : {-1e-3, 1e-3}) {
      glm::dvec3 e(0);
      e[axis] = step;
      if (layerOf(q + e, light, c.layers) != c.layer) return false;
      if (layerOf(q, light + glm::dvec4(e, 0), c.layers) != c.layer) return false;
    }
  return true;
}

// A random point in the cube and a random light: a point outside the cube, one inside, or a
// direction; each face's map a random layer, or none (-1) one time in four.
inline FaceCall randomCall(std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u(-1, 1);
  std::uniform_int_distribution<int> kind(0, 2), layer(0, 5), none(0, 3);
  for (;;) {
    FaceCall c;
    c.q = 0.95f * glm::vec3(u(rng), u(rng), u(rng));
    const int k = kind(rng);
    const glm::vec3 r(u(rng), u(rng), u(rng));
    if (k == 0 && glm::length(r) > 0.1f) c.light = glm::vec4(glm::normalize(r), 0);
    else if (k == 1) c.light = glm::vec4(0.8f * r, 1);
    else c.light = glm::vec4(4.0f * r, 1);
    if (k == 2 && glm::max(std::abs(c.light.x), glm::max(std::abs(c.light.y), std::abs(c.light.z))) < 1.3f) continue;
    for (int& l : c.layers) l = none(rng) == 0 ? -1 : layer(rng);
    if (decide(c)) return c;
  }
}

// Four random calls, the last one certainly on some face's map: the reference GLSL's values; the
// stub's -1 fails the last.
inline GlslCase randomFaces(std::mt19937_64& rng, const std::string& name) {
  std::string e = "vec4(";
  for (int k = 0; k < 3; ++k) e += glsl(randomCall(rng)) + ", ";
  FaceCall last;
  do last = randomCall(rng);
  while (last.layer < 0);
  return {name + " (seed " + std::to_string(grading::seed()) + ")",
          e + glsl(last) + ")",
          std::nullopt,
          0,
          4,
          "each component: cubeFaceLayer(q, light, layerOfFace) of a random point, light and face set"};
}

}  // namespace shadowlab::ex09glsl

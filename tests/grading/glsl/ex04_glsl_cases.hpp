#pragma once
// Lesson 04's GLSL cases, shared by the public (glsl/ex04_glsl.cpp) and hidden
// (hidden/ex04_glsl_hidden.cpp) ones: how a case reads extrudeToInfinity's answer (a point at
// infinity is a direction: any positive multiple is the same point) and the random extrusions.
#include <random>
#include <string>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"

namespace shadowlab::ex04glsl {

// vec4(the unit direction, w): (p - L, 0) and (2 (p - L), 0) project to the same point, so the
// cases compare the direction, not the length; a finite point (w != 0) or a direction toward the
// light still fails.
inline const char* const kPrelude = R"(
vec4 caseDirection(vec4 h) { return vec4(length(h.xyz) > 0.0 ? normalize(h.xyz) : h.xyz, h.w); }
)";
inline const char* const kNote =
    "compared: vec4(normalize(xyz), w) of your answer (a point at infinity is a direction, any length); "
    "light = (position, 1) for a point light, (-direction, 0) for a directional one";

inline std::string v3(const glm::vec3& v) {
  return "vec3(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ")";
}

// One extrusion: a point light anywhere in a 20 m box with the vertex at least 1 m from it, or a
// directional light from a random direction; the reference GLSL's value.
inline GlslCase randomExtrusion(std::mt19937_64& rng, const std::string& name, bool directional) {
  std::uniform_real_distribution<float> u(-10, 10);
  const glm::vec3 p(u(rng), u(rng), u(rng));
  glm::vec4 light;
  if (directional) {
    glm::vec3 d(0);
    while (glm::length(d) < 0.1f) d = glm::vec3(u(rng), u(rng), u(rng));
    light = glm::vec4(-glm::normalize(d), 0);
  } else {
    glm::vec3 l = p;
    while (glm::distance(l, p) < 1) l = glm::vec3(u(rng), u(rng), u(rng));
    light = glm::vec4(l, 1);
  }
  return {name + (directional ? " (directional" : " (point") + ", seed " + std::to_string(grading::seed()) + ")",
          "caseDirection(extrudeToInfinity(" + v3(p) + ", " + glslVec(light) + "))",
          std::nullopt,
          1e-5f,
          4,
          std::string(kNote) + "; p = " + v3(p) + ", light = " + glslVec(light)};
}

}  // namespace shadowlab::ex04glsl

#pragma once
// The hidden renders' random placements, shared by lessons 08 and 09's hidden GLSL cases: a sun
// from a random azimuth at least `minDown` down, and a random camera yaw, as the lesson's --set
// arguments.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/glsl_cases.hpp"

namespace shadowlab::glslcases {

inline std::vector<std::string> randomSunAndCamera(std::mt19937_64& rng, float minDown) {
  std::uniform_real_distribution<float> u(0, 1);
  const float a = 6.2832f * u(rng);
  const glm::vec3 sun = glm::normalize(glm::vec3(std::cos(a), -(minDown + u(rng)), std::sin(a)));
  return {"--set", "light0.direction=" + glslFloat(sun.x) + " " + glslFloat(sun.y) + " " + glslFloat(sun.z), "--set",
          "camera.yaw=" + glslFloat(6.2832f * u(rng))};
}

}  // namespace shadowlab::glslcases

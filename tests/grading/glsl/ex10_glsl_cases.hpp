#pragma once
// Lesson 10's GLSL cases, shared by the public (glsl/ex10_glsl.cpp) and hidden
// (hidden/ex10_glsl_hidden.cpp) ones: the prelude that stands in for shadow_cascades.frag's
// uniforms, and the random cases, whose expected values are shadow::cascadeAt's on the same (float)
// inputs.
#include <random>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/cascades.hpp"
#include "app/glsl_cases.hpp"

namespace shadowlab::ex10glsl {

// shadow_cascades.frag's uniforms as plain globals of two lights, and cascadeCase: light `light`
// gets the case's cascades, the other light a decoy set (4 cascades from 0.5 to 40, no band) that
// an answer reading the wrong light's cascades picks from. Returns (k, nextWeight, 0, 0).
inline const char* const kPrelude = R"(int uPsmLayers[2];
float uCsmNear;
vec4 uCsmFar[2];
float uCsmBand;
int cascadeAt(int light, float depth, out float nextWeight);
vec4 cascadeCase(int light, int count, float zNear, vec4 zFar, float band, float depth) {
  uPsmLayers[light] = count;
  uPsmLayers[1 - light] = 4;
  uCsmNear = zNear;
  uCsmFar[light] = zFar;
  uCsmFar[1 - light] = vec4(10.0, 20.0, 30.0, 40.0);
  uCsmBand = band;
  float w = 0.0;
  int k = cascadeAt(light, depth, w);
  return vec4(float(k), w, 0.0, 0.0);
}
)";

// GLSL of cascadeCase's call on float inputs (far: count of them, the rest padded with the last).
inline std::string cascadeCall(int light, const std::vector<float>& splits, float band, float depth) {
  glm::vec4 far(splits.back());
  for (std::size_t i = 1; i < splits.size(); ++i) far[int(i) - 1] = splits[i];
  return "cascadeCase(" + std::to_string(light) + ", " + std::to_string(splits.size() - 1) + ", " +
         glslFloat(splits.front()) + ", " + glslVec(far) + ", " + glslFloat(band) + ", " + glslFloat(depth) + ")";
}

// shadow::cascadeAt on the same float inputs, in double (the shader rounds each step to float: the
// weight's tolerance, 1e-5, holds with band >= 0.2, see ex10_glsl.cpp).
inline shadow::CascadeBlend expected(const std::vector<float>& splits, float band, float depth) {
  const std::vector<double> s(splits.begin(), splits.end());
  return shadow::cascadeAt(std::span<const double>(s), depth, band);
}

// A random cascade set (1 to 4 cascades, practical splits of [0.1, 2] .. 5 to 50 times that,
// lambda in [0, 1], band in [0.2, 0.5]) and two depths in it: x y the first depth's (k, weight),
// inside the blend band of a cascade that is not the last (in the only one with one cascade), so
// k >= 0 and the stub's -1 fails; z w a depth anywhere in [zNear, zFar] or up to 10 % beyond
// either end (k = -1 there). Both on light 0 or 1 at random.
inline GlslCase randomChoices(std::mt19937_64& rng, const std::string& name) {
  std::uniform_real_distribution<float> u(0, 1);
  const int count = std::uniform_int_distribution<int>(1, 4)(rng);
  const float zn = 0.1f + 1.9f * u(rng), zf = zn * (5 + 45 * u(rng));
  std::vector<float> splits;
  for (double d : shadow::cascadeSplits(zn, zf, count, u(rng))) splits.push_back(float(d));
  const float band = 0.2f + 0.3f * u(rng);
  const int k = std::uniform_int_distribution<int>(0, std::max(0, count - 2))(rng);
  const float a = splits[std::size_t(k)], b = splits[std::size_t(k) + 1];
  const float d1 = count == 1 ? a + (b - a) * u(rng) : b - band * (b - a) * u(rng);
  const float d2 = zn - 0.1f * (zf - zn) + 1.2f * (zf - zn) * u(rng);
  const int light = std::uniform_int_distribution<int>(0, 1)(rng);
  const shadow::CascadeBlend e1 = expected(splits, band, d1), e2 = expected(splits, band, d2);
  std::string list;
  for (float s : splits) list += (list.empty() ? "" : " ") + glslFloat(s);
  return {name + " (seed " + std::to_string(grading::seed()) + ")",
          "vec4(" + cascadeCall(light, splits, band, d1) + ".xy, " + cascadeCall(light, splits, band, d2) + ".xy)",
          glm::vec4(float(e1.cascade), float(e1.nextWeight), float(e2.cascade), float(e2.nextWeight)),
          1e-5f,
          4,
          "light " + std::to_string(light) + ", splits " + list + ", band " + glslFloat(band) +
              "; x y: (k, weight) at depth " + glslFloat(d1) + ", z w: at depth " + glslFloat(d2)};
}

}  // namespace shadowlab::ex10glsl

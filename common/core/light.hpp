#pragma once
// Light sources as the whole course sees them: lessons shade with them, shadow techniques fit
// cameras to them, and the ground truth (common/measure) traces rays toward them.
#include <glm/glm.hpp>

namespace shadowlab {

// The most lights a lit shader takes (MAX_LIGHTS in shaders/common/light.glsl): every lesson,
// technique and draw call counts to this one number.
inline constexpr int kMaxLights = 4;

enum class LightKind { Point, Spot, Directional };
enum class AreaShape { None, Sphere, Rectangle };  // soft shadows: the emitter's extent

struct Light {
  LightKind kind = LightKind::Point;
  glm::vec3 position{0.0f, 8.0f, 0.0f};    // Point, Spot (world)
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // Spot axis, Directional: the direction light TRAVELS (unit)
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  // f_att = 1 / (c0 + c1 d + c2 d^2), the lecture's attenuation ([Tarantsev-L12]); directional: none.
  glm::vec3 attenuation{1.0f, 0.0f, 0.01f};
  float spotInner = 0.35f, spotOuter = 0.5f;  // half-angles in radians (smooth fall-off between)
  AreaShape area = AreaShape::None;
  float radius = 0.5f;                  // Sphere: emitter radius
  glm::vec2 size{1.0f, 1.0f};           // Rectangle: extent along `tangent` and direction x tangent
  glm::vec3 tangent{1.0f, 0.0f, 0.0f};  // Rectangle: first edge direction (unit)
  bool enabled = true;

  // Unit vector from surface point p toward the light (L in the lecture's formula).
  glm::vec3 toLight(const glm::vec3& p) const {
    return kind == LightKind::Directional ? -direction : glm::normalize(position - p);
  }
  // Distance from p to the light (infinite for directional lights).
  float distanceTo(const glm::vec3& p) const {
    return kind == LightKind::Directional ? 1e30f : glm::length(position - p);
  }
};

}  // namespace shadowlab

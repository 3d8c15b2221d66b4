#include "core/light_rig.hpp"

namespace shadowlab {

std::array<Light, 4> courseRig() {
  auto make = [](LightKind k, glm::vec3 pos, glm::vec3 dir, glm::vec3 color, float intensity, glm::vec3 att, bool on) {
    Light l{k, pos};
    l.direction = glm::normalize(dir), l.color = color, l.intensity = intensity, l.attenuation = att, l.enabled = on;
    return l;
  };
  return {
      make(LightKind::Directional, {}, {-0.4f, -1.0f, -0.3f}, {1.0f, 0.95f, 0.85f}, 0.7f, {1, 0, 0}, true),
      make(LightKind::Point, {3.0f, 3.0f, 2.0f}, {0, -1, 0}, {1.0f, 0.6f, 0.3f}, 2.0f, {1.0f, 0.1f, 0.05f}, true),
      make(LightKind::Spot, {-3.0f, 5.0f, 3.0f}, {0.5f, -1.0f, -0.5f}, {0.4f, 0.6f, 1.0f}, 3.0f, {1.0f, 0.05f, 0.02f},
           false),
      make(LightKind::Point, {-3.0f, 2.5f, -2.5f}, {0, -1, 0}, {0.5f, 1.0f, 0.5f}, 2.0f, {1.0f, 0.2f, 0.1f}, false)};
}

Light off(Light light) {
  light.enabled = false;
  return light;
}

Light courseSun(const glm::vec3& direction) {
  Light l{LightKind::Directional};
  l.direction = glm::normalize(direction);
  l.color = {1.0f, 0.95f, 0.85f};
  l.intensity = 0.9f;
  return l;
}

Light courseLamp(const glm::vec3& position) {
  Light l{LightKind::Point, position};
  l.color = {1.0f, 0.6f, 0.3f};
  l.intensity = 3.0f;
  l.attenuation = {1.0f, 0.05f, 0.02f};
  l.enabled = false;
  return l;
}

Light showcaseSphereSpot() {
  Light l{LightKind::Spot, {0.96f, 7.0f, -1.62f}};
  l.direction = glm::normalize(glm::vec3(-2.46f, -7.0f, 0.62f));
  l.color = {1.0f, 0.95f, 0.85f};
  l.intensity = 1.3f;
  l.attenuation = {1.0f, 0.0f, 0.002f};
  l.spotInner = 0.9f;  // the cone holds every shape and its shadow: the maps' fov is 2.05 rad
  l.spotOuter = 1.0f;
  l.area = AreaShape::Sphere;
  l.radius = 0.5f;
  return l;
}

Light secondSphereSpot() {
  Light l{LightKind::Spot, {6.0f, 7.0f, 5.0f}};
  l.direction = glm::normalize(glm::vec3(-6.0f, -7.0f, -5.0f));
  l.color = {0.5f, 0.7f, 1.0f};
  l.intensity = 0.8f;
  l.attenuation = {1.0f, 0.0f, 0.002f};
  l.spotInner = 0.6f;
  l.spotOuter = 0.72f;
  l.area = AreaShape::Sphere;
  l.radius = 0.3f;
  l.enabled = false;
  return l;
}

namespace {
// A spot at `position` aimed at the origin, attenuated by 1 + c2 d^2, its cone's core and edge
// half-angles `inner` and `outer` (radians).
Light spotAtOrigin(const glm::vec3& position, const glm::vec3& color, float intensity, float c2, float inner,
                   float outer) {
  Light l{LightKind::Spot, position};
  l.direction = glm::normalize(-position);
  l.color = color;
  l.intensity = intensity;
  l.attenuation = {1.0f, 0.0f, c2};
  l.spotInner = inner;
  l.spotOuter = outer;
  return l;
}
}  // namespace

Light forestSpot() { return spotAtOrigin({14.0f, 26.0f, 10.0f}, {1.0f, 0.95f, 0.85f}, 1.6f, 0.0f, 0.45f, 0.6f); }

Light citySpot() { return off(spotAtOrigin({-12.0f, 16.0f, 10.0f}, {0.5f, 0.7f, 1.0f}, 2.0f, 0.002f, 0.35f, 0.5f)); }

Light cityHighSpot() {
  return off(spotAtOrigin({-14.0f, 18.0f, 12.0f}, {0.6f, 0.75f, 1.0f}, 2.5f, 0.0015f, 0.4f, 0.55f));
}

}  // namespace shadowlab

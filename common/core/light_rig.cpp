#include "core/light_rig.hpp"

namespace shadowlab {

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

}  // namespace shadowlab

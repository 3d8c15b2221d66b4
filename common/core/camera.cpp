#include "core/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

namespace {
// Just short of the poles: at exactly +-pi/2 the forward vector is parallel to world up and
// lookAt has no defined right vector.
constexpr float kPitchLimit = 1.5707963f - 1e-3f;

float clampPitch(float pitch) { return std::clamp(pitch, -kPitchLimit, kPitchLimit); }

// Unit vector for a yaw around +y (0 looks along -z) and a pitch above the horizon.
glm::vec3 direction(float yaw, float pitch) {
  const float cp = std::cos(pitch);
  return {-std::sin(yaw) * cp, std::sin(pitch), -std::cos(yaw) * cp};
}

glm::mat4 perspective(float fovY, float aspect, float nearZ, float farZ) {
  // A zero-height window reports aspect 0; glm would divide by it.
  return glm::perspective(fovY, std::max(aspect, 1e-6f), nearZ, farZ);
}
}  // namespace

// ---- OrbitCamera: the eye sits on a sphere around the target, pitch lifts it above the horizon.
glm::vec3 OrbitCamera::forward() const { return direction(yaw, -clampPitch(pitch)); }

glm::vec3 OrbitCamera::position() const { return target - std::clamp(distance, minDistance, maxDistance) * forward(); }

void OrbitCamera::lookFrom(const glm::vec3& eye, const glm::vec3& at) {
  const glm::vec3 d = at - eye;
  const float length = glm::length(d);
  if (!(length > 0.0f)) throw std::invalid_argument("OrbitCamera::lookFrom: the eye is at the target");
  const glm::vec3 f = d / length;  // forward = direction(yaw, -pitch), inverted
  target = at;
  distance = length;
  pitch = clampPitch(-std::asin(std::clamp(f.y, -1.0f, 1.0f)));
  yaw = std::atan2(-f.x, -f.z);
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(position(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::projection(float aspect) const { return perspective(fovY, aspect, nearZ, farZ); }

void OrbitCamera::orbit(float dYaw, float dPitch) {
  yaw = std::remainder(yaw + dYaw, 6.2831853f);  // keeps yaw small so float precision holds
  pitch = clampPitch(pitch + dPitch);
}

void OrbitCamera::lookAround(float dYaw, float dPitch) {
  const glm::vec3 eye = position();
  orbit(dYaw, dPitch);
  target = eye + std::clamp(distance, minDistance, maxDistance) * forward();
}

void OrbitCamera::fly(const glm::vec3& local) {
  const glm::vec3 f = forward();  // pitch is clamped short of +-pi/2: never parallel to world up
  const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  target += right * local.x + glm::vec3(0, local.y, 0) + f * local.z;
}

OrbitCamera frameBox(const OrbitCamera& base, const glm::vec3& lo, const glm::vec3& hi, float aspect,
                     float distanceFactor) {
  OrbitCamera c = base;
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  const float halfFov = 0.5f * std::min(c.fovY, 2.0f * std::atan(std::tan(0.5f * c.fovY) * aspect));
  c.target = 0.5f * (lo + hi);
  c.distance = distanceFactor * radius / std::sin(halfFov);
  c.maxDistance = std::max(c.maxDistance, c.distance);
  c.minDistance = std::min(c.minDistance, c.distance);
  c.nearZ = std::max(c.distance - 2.0f * radius, c.distance * 1e-3f);
  c.farZ = std::max(c.farZ, c.distance + 2.0f * radius);
  return c;
}

void OrbitCamera::aim(const glm::vec3& t, float d, float p) {
  target = t;
  distance = d;
  pitch = p;
}

void OrbitCamera::zoom(float factor) {
  if (!(factor > 0.0f)) return;  // a zero or negative factor has no meaning for a distance
  distance = std::clamp(distance * factor, minDistance, maxDistance);
}

void OrbitCamera::pan(const glm::vec2& delta) {
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, f);
  // Scaling by distance makes the same mouse motion move the scene by the same screen fraction.
  target += (right * delta.x + up * delta.y) * distance;
}

// ---- FlyCamera: first-person, pitch looks up.
glm::vec3 FlyCamera::forward() const { return direction(yaw, clampPitch(pitch)); }

glm::vec3 FlyCamera::right() const { return {std::cos(yaw), 0.0f, -std::sin(yaw)}; }

glm::mat4 FlyCamera::view() const { return glm::lookAt(position, position + forward(), glm::vec3(0, 1, 0)); }

glm::mat4 FlyCamera::projection(float aspect) const { return perspective(fovY, aspect, nearZ, farZ); }

void FlyCamera::look(float dYaw, float dPitch) {
  yaw = std::remainder(yaw + dYaw, 6.2831853f);
  pitch = clampPitch(pitch + dPitch);
}

void FlyCamera::move(const glm::vec3& local) {
  position += right() * local.x + glm::vec3(0, 1, 0) * local.y + forward() * local.z;
}

std::string sightProblem(const OrbitCamera& camera, float aspect, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::mat4 view = camera.view(), clip = camera.projection(aspect) * view;
  float nearest = 1e30f, farthest = -1e30f;  // view depth along the view axis
  int outside[6] = {};                       // corners beyond each clip plane: x<-w, x>w, y<-w, y>w, z<-w, z>w
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z, 1.0f);
    const float depth = -(view * p).z;
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
    const glm::vec4 c = clip * p;
    for (int axis = 0; axis < 3; ++axis) {
      outside[2 * axis] += c[axis] < -c.w;
      outside[2 * axis + 1] += c[axis] > c.w;
    }
  }
  auto metres = [](float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(v));
    return std::string(buf);
  };
  if (farthest <= 0.0f) return "the scene is behind the camera";
  if (nearest > camera.farZ)
    return "the scene is beyond the far plane (its nearest point " + metres(nearest) + " away, camera.far " +
           metres(camera.farZ) + ")";
  if (farthest < camera.nearZ)
    return "the scene is nearer than the near plane (its farthest point " + metres(farthest) + " away, camera.near " +
           metres(camera.nearZ) + ")";
  for (int plane = 0; plane < 4; ++plane)
    if (outside[plane] == 8)
      return "the scene is outside the field of view (to the " +
             std::string(plane == 0   ? "left"
                         : plane == 1 ? "right"
                         : plane == 2 ? "bottom"
                                      : "top") +
             " of it: look at camera.target)";
  return "";
}

}  // namespace shadowlab

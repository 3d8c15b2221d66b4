#pragma once
// Cameras as pure GLM maths: no input, no GL. The app layer maps mouse and keys onto these calls.
// Right-handed view space looking down -z; projections map depth to GL's [-1,1] clip range.
#include <string>

#include <glm/glm.hpp>

namespace shadowlab {

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float yaw = 0.6f;        // radians around +y, 0 looks along -z
  float pitch = 0.45f;     // radians above the horizon, clamped to (-pi/2, pi/2)
  float distance = 12.0f;  // from target, clamped to [minDistance, maxDistance]
  float fovY = 0.873f;     // radians (50 degrees)
  float nearZ = 0.1f, farZ = 200.0f;
  float minDistance = 0.2f, maxDistance = 1000.0f;

  glm::vec3 position() const;
  glm::vec3 forward() const;  // unit, from position toward target
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  void orbit(float dYaw, float dPitch);
  void zoom(float factor);           // distance *= factor
  void pan(const glm::vec2& delta);  // moves target in the view plane, scaled by distance
  // A starting view: look at `target` from `distance`, `pitch` above the horizon (yaw kept).
  void aim(const glm::vec3& target, float distance, float pitch);
  // Sets target, distance, yaw and pitch so the eye is at `eye` looking at `target` (replaying a
  // recorded path). Throws std::invalid_argument when the two points coincide.
  void lookFrom(const glm::vec3& eye, const glm::vec3& target);
  // The fly camera's moves, on the same state (so recorded paths and presets serve both modes):
  // turn the view about the eye (the eye stays where it is; the target swings round it), and move
  // eye and target together by `local` (x right, y world up, z forward along the view), as FlyCamera::move does.
  void lookAround(float dYaw, float dPitch);
  void fly(const glm::vec3& local);
};

// `base` (its yaw, pitch, field of view) moved to look at the box [lo, hi] from `distanceFactor`
// times the distance at which the box's bounding sphere just fits the narrower field of view of an
// `aspect` image; near and far planes around the sphere. The god view frames the scene with it.
OrbitCamera frameBox(const OrbitCamera& base, const glm::vec3& lo, const glm::vec3& hi, float aspect,
                     float distanceFactor);

struct FlyCamera {
  glm::vec3 position{0.0f, 2.0f, 8.0f};
  float yaw = 0.0f;    // radians around +y, 0 looks along -z
  float pitch = 0.0f;  // clamped to (-pi/2, pi/2)
  float fovY = 0.873f;
  float nearZ = 0.1f, farZ = 200.0f;

  glm::vec3 forward() const;
  glm::vec3 right() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  void look(float dYaw, float dPitch);
  void move(const glm::vec3& local);  // x right, y up (world), z forward
};

// Why the camera sees none of the box [lo, hi] (the scene), "" when its frustum may meet it: the
// box lies behind the eye, beyond the far plane, wholly nearer than the near plane, or outside the
// field of view. Conservative: "" whenever no single frustum plane has the whole box outside it.
// The framework says it in the banner (and on stderr headless) instead of drawing one colour.
std::string sightProblem(const OrbitCamera& camera, float aspect, const glm::vec3& lo, const glm::vec3& hi);

}  // namespace shadowlab

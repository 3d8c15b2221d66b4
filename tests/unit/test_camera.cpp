// Cameras: positions from yaw/pitch/distance by hand, view matrices that put the target on -z,
// clamps, and projections that map near and far to GL's -1 and +1.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "core/camera.hpp"

using namespace shadowlab;

namespace {
constexpr float kPi = 3.14159265358979f;

void checkVec(const glm::vec3& got, const glm::vec3& want, float eps = 1e-4f) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", " << want.y << ", " << want.z
               << ")");
  CHECK(glm::length(got - want) < eps);
}

glm::vec3 transformPoint(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }
}  // namespace

TEST_CASE("camera: orbit position at known yaw, pitch and distance") {
  OrbitCamera cam;
  cam.target = {1.0f, 2.0f, 3.0f};
  cam.distance = 5.0f;
  cam.yaw = 0.0f;
  cam.pitch = 0.0f;
  checkVec(cam.position(), {1.0f, 2.0f, 8.0f});  // yaw 0 looks along -z, so the eye is on +z
  checkVec(cam.forward(), {0.0f, 0.0f, -1.0f});
  cam.yaw = 0.5f * kPi;  // a quarter turn around +y: looking along -x
  checkVec(cam.position(), {6.0f, 2.0f, 3.0f});
  cam.yaw = 0.0f;
  cam.pitch = kPi / 6.0f;  // 30 degrees above the horizon: up by 5 sin 30, back by 5 cos 30
  checkVec(cam.position(), {1.0f, 2.0f + 2.5f, 3.0f + 5.0f * std::sqrt(3.0f) / 2.0f});
  CHECK(glm::length(cam.forward()) == doctest::Approx(1.0f));
  checkVec(cam.forward(), glm::normalize(cam.target - cam.position()));
}

TEST_CASE("camera: orbit view maps the target onto the -z axis at its distance") {
  OrbitCamera cam;
  cam.target = {-3.0f, 0.5f, 7.0f};
  for (float yaw : {0.0f, 1.0f, -2.5f, 3.0f})
    for (float pitch : {-1.2f, 0.0f, 0.45f, 1.4f}) {
      cam.yaw = yaw;
      cam.pitch = pitch;
      cam.distance = 9.0f;
      checkVec(transformPoint(cam.view(), cam.target), {0.0f, 0.0f, -9.0f});
      checkVec(transformPoint(cam.view(), cam.position()), glm::vec3(0.0f));
    }
}

TEST_CASE("camera: orbit pitch and zoom are clamped") {
  OrbitCamera cam;
  cam.orbit(0.0f, 10.0f);
  CHECK(cam.pitch < 0.5f * kPi);
  CHECK(cam.pitch > 0.5f * kPi - 0.01f);
  cam.orbit(0.0f, -20.0f);
  CHECK(cam.pitch > -0.5f * kPi);
  CHECK(cam.pitch < -0.5f * kPi + 0.01f);
  const glm::mat4 v = cam.view();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) CHECK(std::isfinite(v[c][r]));  // lookAt never sees forward == up

  cam.distance = 12.0f;
  cam.zoom(0.5f);
  CHECK(cam.distance == doctest::Approx(6.0f));
  cam.zoom(1e-6f);
  CHECK(cam.distance == cam.minDistance);
  cam.zoom(1e9f);
  CHECK(cam.distance == cam.maxDistance);
  cam.zoom(-1.0f);  // meaningless factors leave the distance alone
  CHECK(cam.distance == cam.maxDistance);
}

TEST_CASE("camera: orbit pan moves the target across the view, scaled by distance") {
  OrbitCamera cam;
  cam.yaw = 0.0f;
  cam.pitch = 0.0f;
  cam.distance = 4.0f;
  cam.pan({0.5f, 0.25f});
  // Looking along -z: right is +x, up is +y.
  checkVec(cam.target, {2.0f, 1.0f, 0.0f});
}

TEST_CASE("camera: fly forward and right are orthonormal, right stays horizontal") {
  FlyCamera cam;
  for (float yaw : {0.0f, 0.7f, -2.0f, 3.1f})
    for (float pitch : {-1.3f, 0.0f, 0.9f}) {
      cam.yaw = yaw;
      cam.pitch = pitch;
      const glm::vec3 f = cam.forward(), r = cam.right();
      CHECK(glm::length(f) == doctest::Approx(1.0f));
      CHECK(glm::length(r) == doctest::Approx(1.0f));
      CHECK(glm::dot(f, r) == doctest::Approx(0.0f).epsilon(1e-6));
      CHECK(r.y == 0.0f);
      // The view looks along forward: one unit ahead lands on -z.
      checkVec(transformPoint(cam.view(), cam.position + f), {0.0f, 0.0f, -1.0f});
    }
  cam.yaw = 0.5f * kPi;
  cam.pitch = 0.0f;
  checkVec(cam.forward(), {-1.0f, 0.0f, 0.0f});
  checkVec(cam.right(), {0.0f, 0.0f, -1.0f});
  cam.look(0.0f, 5.0f);
  CHECK(cam.pitch < 0.5f * kPi);
}

TEST_CASE("camera: fly moves along its own axes, up along world y") {
  FlyCamera cam;
  cam.position = {0.0f, 2.0f, 8.0f};
  cam.yaw = 0.0f;
  cam.pitch = 0.0f;
  cam.move({1.0f, 0.0f, 0.0f});
  checkVec(cam.position, {1.0f, 2.0f, 8.0f});
  cam.move({0.0f, 0.0f, 2.0f});
  checkVec(cam.position, {1.0f, 2.0f, 6.0f});
  cam.pitch = 0.5f * kPi / 3.0f;  // looking 30 degrees up: y stays world-up
  cam.move({0.0f, 3.0f, 0.0f});
  checkVec(cam.position, {1.0f, 5.0f, 6.0f});
  cam.move({0.0f, 0.0f, 1.0f});
  checkVec(cam.position, {1.0f, 5.5f, 6.0f - std::sqrt(3.0f) / 2.0f});
}

TEST_CASE("camera: projections map near to -1 and far to +1") {
  OrbitCamera orbit;
  orbit.nearZ = 0.5f;
  orbit.farZ = 300.0f;
  FlyCamera fly;
  fly.nearZ = 0.1f;
  fly.farZ = 50.0f;
  struct Case {
    glm::mat4 p;
    float n, f;
  } cases[] = {{orbit.projection(16.0f / 9.0f), 0.5f, 300.0f}, {fly.projection(1.0f), 0.1f, 50.0f}};
  for (const Case& c : cases) {
    const glm::vec4 nearClip = c.p * glm::vec4(0.0f, 0.0f, -c.n, 1.0f);
    const glm::vec4 farClip = c.p * glm::vec4(0.0f, 0.0f, -c.f, 1.0f);
    CHECK(nearClip.z / nearClip.w == doctest::Approx(-1.0f));
    CHECK(farClip.z / farClip.w == doctest::Approx(1.0f).epsilon(1e-4));
  }
  // The vertical field of view reaches the top edge: tan(fov/2) * depth maps to y = 1.
  const glm::mat4 p = fly.projection(2.0f);
  const float y = std::tan(0.5f * fly.fovY) * 10.0f;
  const glm::vec4 top = p * glm::vec4(0.0f, y, -10.0f, 1.0f);
  CHECK(top.y / top.w == doctest::Approx(1.0f));
  const glm::vec4 side = p * glm::vec4(2.0f * y, 0.0f, -10.0f, 1.0f);  // aspect 2
  CHECK(side.x / side.w == doctest::Approx(1.0f));
  // A collapsed window does not produce infinities.
  const glm::mat4 degenerate = fly.projection(0.0f);
  CHECK(std::isfinite(degenerate[0][0]));
}

TEST_CASE("camera: lookFrom puts the orbit camera's eye where a recorded path had it") {
  shadowlab::OrbitCamera c;
  const glm::vec3 eye(3, 4, -5), target(1, 0.5f, 2);
  c.lookFrom(eye, target);
  CHECK(glm::length(c.position() - eye) < 1e-4f);
  CHECK(glm::length(c.target - target) < 1e-6f);
  CHECK(c.distance == doctest::Approx(glm::length(eye - target)));
  // Straight down the -z axis from +z: yaw 0, pitch 0 by the camera's own convention.
  c.lookFrom({0, 0, 10}, {0, 0, 0});
  CHECK(c.yaw == doctest::Approx(0.0f));
  CHECK(c.pitch == doctest::Approx(0.0f));
  CHECK_THROWS_AS(c.lookFrom(target, target), std::invalid_argument);
}

TEST_CASE("camera: the orbit camera's fly mode turns about the eye and moves eye and target together") {
  OrbitCamera cam;
  cam.aim({1.0f, 0.0f, -2.0f}, 10.0f, 0.3f);
  cam.yaw = 0.4f;
  const glm::vec3 eye = cam.position();
  cam.lookAround(0.7f, -0.2f);
  checkVec(cam.position(), eye);  // the eye stays
  CHECK(cam.yaw == doctest::Approx(1.1f));
  CHECK(cam.pitch == doctest::Approx(0.1f));
  CHECK(glm::length(cam.target - eye) == doctest::Approx(10.0f));
  cam.lookAround(0.0f, 5.0f);  // pitch clamped: never looking straight up
  CHECK(cam.pitch < 0.5f * kPi);
  checkVec(cam.position(), eye);

  cam.yaw = 0.0f;
  cam.pitch = 0.0f;  // looking along -z, level
  cam.target = cam.position() + glm::vec3(0, 0, -10.0f);
  const glm::vec3 start = cam.position();
  cam.fly({1.0f, 0.0f, 0.0f});
  checkVec(cam.position(), start + glm::vec3(1, 0, 0));
  cam.fly({0.0f, 2.0f, 3.0f});
  checkVec(cam.position(), start + glm::vec3(1, 2, -3));
  cam.pitch = kPi / 6.0f;  // the eye above the target, looking 30 degrees down: forward follows the view
  cam.target = glm::vec3(0.0f);
  cam.fly({0.0f, 0.0f, 1.0f});
  checkVec(cam.target, {0.0f, -0.5f, -std::sqrt(3.0f) / 2.0f});
}

TEST_CASE("camera: frameBox puts every corner of the box inside the image, from any side") {
  const glm::vec3 lo(-30.0f, 0.0f, -30.0f), hi(30.0f, 25.0f, 30.0f);  // a city block and its lights
  for (float aspect : {16.0f / 9.0f, 1.0f, 0.5f})
    for (float yaw : {0.0f, 0.9f, 2.5f})
      for (float factor : {1.0f, 1.5f}) {
        OrbitCamera base;
        base.yaw = yaw;
        base.pitch = 0.6f;
        const OrbitCamera c = frameBox(base, lo, hi, aspect, factor);
        const glm::mat4 viewProj = c.projection(aspect) * c.view();
        float extent = 0.0f;
        for (int i = 0; i < 8; ++i) {
          const glm::vec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
          const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
          INFO("aspect " << aspect << " yaw " << yaw << " factor " << factor << " corner " << i);
          REQUIRE(clip.w > 0.0f);
          const glm::vec3 ndc = glm::vec3(clip) / clip.w;
          CHECK(std::abs(ndc.x) <= 1.0f);
          CHECK(std::abs(ndc.y) <= 1.0f);
          CHECK(std::abs(ndc.z) <= 1.0f);  // between the near and far planes
          extent = std::max({extent, std::abs(ndc.x), std::abs(ndc.y)});
        }
        CHECK(extent > 0.4f / factor);  // and not a dot in the middle
      }
}

// A camera that sees none of the scene says why (the framework's banner), and one that sees any of
// it says nothing: beyond far, nearer than near, behind the eye, off to a side.
TEST_CASE("sightProblem: why a camera sees none of the scene") {
  const glm::vec3 lo(-5.0f, 0.0f, -5.0f), hi(5.0f, 10.0f, 5.0f);
  OrbitCamera cam;  // 12 from the origin, looking at it
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).empty());
  cam.nearZ = 0.01f;
  cam.distance = 50.0f;
  cam.farZ = 20.0f;
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).find("beyond the far plane") != std::string::npos);
  cam.farZ = 200.0f;
  cam.distance = 30.0f;
  cam.nearZ = 25.0f;  // the box spans depths of about 22 to 38: the near plane cuts it
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).empty());
  cam.nearZ = 45.0f;
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).find("nearer than the near plane") != std::string::npos);
  cam.nearZ = 0.1f;
  cam.target = glm::vec3(0.0f, 0.0f, 1e4f);  // the eye beyond the box, looking away from it
  cam.yaw = 3.14159265f;                     // looking along +z, away from the origin
  cam.pitch = 0.0f;
  cam.distance = 12.0f;
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).find("behind the camera") != std::string::npos);
  cam.target = glm::vec3(100.0f, 5.0f, 0.0f);  // beside the box, looking along -z past it
  cam.yaw = 0.0f;
  CHECK(sightProblem(cam, 16.0f / 9.0f, lo, hi).find("outside the field of view") != std::string::npos);
}

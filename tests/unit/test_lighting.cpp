#include <doctest/doctest.h>

#include "algorithms/lighting.hpp"
#include "core/light_rig.hpp"

using namespace shadowlab;

TEST_CASE("lighting: the course's light rig is one of each kind, unit directions, sun and bulb on") {
  const auto rig = courseRig();
  REQUIRE(rig.size() == 4);
  CHECK(rig[0].kind == LightKind::Directional);
  CHECK(rig[1].kind == LightKind::Point);
  CHECK(rig[2].kind == LightKind::Spot);
  CHECK(rig[0].enabled);
  CHECK(rig[1].enabled);
  CHECK_FALSE(rig[2].enabled);
  for (const Light& l : rig) CHECK(glm::length(l.direction) == doctest::Approx(1.0f));
  // The sun shines down: its light travels toward -y.
  CHECK(rig[0].direction.y < 0.0f);
}

TEST_CASE("lighting: incident radiance falls off with f_att and vanishes outside a spot's cone") {
  Light bulb;
  bulb.kind = LightKind::Point;
  bulb.position = {0, 4, 0};
  bulb.attenuation = {0, 0, 1};  // inverse square
  bulb.color = glm::vec3(1);
  bulb.intensity = 16;
  CHECK(lighting::incidentRadiance(bulb, {0, 0, 0}).x == doctest::Approx(1.0f));  // 16 / 4^2
  Light spot = bulb;
  spot.kind = LightKind::Spot;
  spot.direction = {0, -1, 0};
  spot.spotInner = 0.2f;
  spot.spotOuter = 0.3f;
  CHECK(lighting::incidentRadiance(spot, {0, 0, 0}).x == doctest::Approx(1.0f));  // on the axis
  CHECK(lighting::incidentRadiance(spot, {4, 0, 0}).x == doctest::Approx(0.0f));  // 45 degrees off
  spot.enabled = false;
  CHECK(lighting::incidentRadiance(spot, {0, 0, 0}).x == 0.0f);
}

// Unit tests for the PSM plan (algorithms/psm/psm_plan), the receiver volumes and potential
// casters (receivers), fix 4's factored matrix (bias) and the post-projective shapes (post_shapes):
// hand-derived values, then seeded random cases.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/bias.hpp"
#include "algorithms/psm/post_shapes.hpp"
#include "algorithms/psm/psm_plan.hpp"
#include "algorithms/psm/receivers.hpp"
#include "algorithms/shadow_math.hpp"
#include "core/mesh_gen.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::psm;

namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
  Aabb b;
  b.min = lo;
  b.max = hi;
  return b;
}

// Eye at (0, 2, 10) looking down -z; fovY 90 degrees, aspect 1, near 1, far 100.
CameraFrustum streetCamera() {
  return makeCamera(lookAlong({0, 2, 10}, {0, 0, -1}), std::numbers::pi / 2, 1.0, 1.0, 100.0);
}

// A ground slab and three blocks in front of the street camera, and one block behind it.
struct Street {
  std::vector<Aabb> receivers{box({-20, 0, -60}, {20, 0.01f, 9}), box({-3, 0, -5}, {-1, 4, -3}),
                              box({2, 0, -20}, {4, 6, -18}), box({-2, 0, -40}, {0, 8, -38})};
  std::vector<Aabb> behind{box({-1, 0, 14}, {1, 10, 16})};  // a tall block 4 m behind the eye
};

// Every key point lands inside one of the plan's maps (clip cube, w > 0).
int pointsOutsideMaps(const PsmPlan& plan, std::span<const glm::dvec3> world) {
  int outside = 0;
  for (const glm::dvec3& p : world) {
    bool in = false;
    for (const PsmMap& m : plan.used()) {
      const glm::dvec4 h = m.camera.worldToClip * glm::dvec4(p, 1.0);
      const glm::dvec3 n = glm::dvec3(h) / h.w;
      in = in || (h.w > 0 && glm::all(glm::lessThanEqual(glm::abs(n), glm::dvec3(1.0 + 1e-6))));
    }
    outside += !in;
  }
  return outside;
}

}  // namespace

TEST_CASE("psm plan: faceMapSize splits a light's texels over its maps") {
  CHECK(faceMapSize(2048, 1) == 2048);
  CHECK(faceMapSize(2048, 4) == 1024);
  CHECK(faceMapSize(2048, 5) == 915);  // floor(2048 / sqrt 5) = floor(915.9)
  CHECK(faceMapSize(1024, 3) == 591);  // floor(591.2)
  CHECK(faceMapSize(1, 6) == 1);
  for (int n = 1; n <= 6; ++n) CHECK(n * faceMapSize(4096, n) * faceMapSize(4096, n) <= 4096 * 4096);
}

TEST_CASE("psm plan: a light in front gets one perspective map holding every key point") {
  const Street s;
  PsmPlanner planner;
  const glm::dvec4 light(0.0, 30.0, -80.0, 1.0);  // a point light far ahead and up
  const PsmPlan& plan = planner.plan(streetCamera(), light, s.receivers, s.receivers, {}, {});
  REQUIRE(plan.status == PlanStatus::Ok);
  CHECK(plan.light.kind == PostLightKind::InFront);
  CHECK(plan.mapCount == 1);
  CHECK(plan.maps[0].camera.kind == LightProjection::Perspective);
  CHECK(pointsOutsideMaps(plan, planner.worldKeyPoints()) == 0);
}

TEST_CASE("psm plan: fix 2 moves the camera's near and far planes onto the key points") {
  const Street s;
  PsmPlanner planner;
  const std::vector<Aabb> blocks(s.receivers.begin() + 1, s.receivers.end());  // no ground
  const PsmPlan& plan = planner.plan(streetCamera(), glm::dvec4(0.3, 1.0, 0.2, 0.0), blocks, blocks, {}, {});
  REQUIRE(plan.status == PlanStatus::Ok);
  // The nearest block corner is at z = -3 (13 in front of the eye), the farthest at z = -40 (50).
  CHECK(plan.camera.zNear == doctest::Approx(13.0).epsilon(1e-5));
  CHECK(plan.camera.zFar == doctest::Approx(50.0).epsilon(1e-5));
  PsmSwitches original;
  original.receiverClipping = false;
  const PsmPlan& all = planner.plan(streetCamera(), glm::dvec4(0.3, 1.0, 0.2, 0.0), blocks, blocks, {}, original);
  CHECK(all.camera.zNear == doctest::Approx(1.0));
  CHECK(all.camera.zFar == doctest::Approx(100.0));
}

TEST_CASE("psm plan: a light behind: fix 1's inverse projection, or the original's slide and reversed map") {
  const Street s;
  PsmPlanner planner;
  const glm::dvec4 sunBehind(0.0, 1.0, 1.0, 0.0);  // comes from behind the eye and above
  const PsmPlan& fixed = planner.plan(streetCamera(), sunBehind, s.receivers, s.receivers, s.behind, {});
  REQUIRE(fixed.status == PlanStatus::Ok);
  CHECK(fixed.realLight.kind == PostLightKind::Behind);
  CHECK(fixed.shift == 0.0);
  CHECK(fixed.maps[0].camera.kind == LightProjection::Inverse);
  CHECK(pointsOutsideMaps(fixed, planner.worldKeyPoints()) == 0);

  PsmSwitches original;
  original.inverseProjection = false;
  const PsmPlan& slid = planner.plan(streetCamera(), sunBehind, s.receivers, s.receivers, s.behind, original);
  REQUIRE(slid.status == PlanStatus::Ok);
  // The block's far side is 6 m behind the eye (z = 16): slide 6 + near 1 = 7.
  CHECK(slid.shift == doctest::Approx(7.0));
  CHECK(slid.camera.zNear == doctest::Approx(8.0));
  CHECK(slid.maps[0].camera.kind == LightProjection::ReversedPerspective);
  CHECK(pointsOutsideMaps(slid, planner.worldKeyPoints()) == 0);
  // No caster behind the eye: nothing to slide for.
  CHECK(planner.plan(streetCamera(), sunBehind, s.receivers, s.receivers, {}, original).shift == 0.0);
}

TEST_CASE("psm plan: fix 3: faces always, faces when the cone is too wide, and a single map capped") {
  const Street s;
  PsmPlanner planner;
  PsmSwitches faces;
  faces.faces = FaceMode::Always;
  const glm::dvec4 sun(0.3, 1.0, -0.2, 0.0);
  const PsmPlan& f = planner.plan(streetCamera(), sun, s.receivers, s.receivers, {}, faces);
  REQUIRE(f.status == PlanStatus::Ok);
  CHECK(f.faces);
  CHECK(f.mapCount == hiddenFaceCount(f.light));
  CHECK(f.mapCount >= 3);
  CHECK(pointsOutsideMaps(f, planner.worldKeyPoints()) == 0);

  // A point light among the receivers (above the street, inside the frustum): no cone holds them.
  const glm::dvec4 lamp(0.0, 1.0, -10.0, 1.0);
  const PsmPlan& a = planner.plan(streetCamera(), lamp, s.receivers, s.receivers, {}, {});
  REQUIRE(a.status == PlanStatus::Ok);
  CHECK(a.faces);
  CHECK(a.mapCount == 6);  // the light is inside the unit cube
  CHECK(pointsOutsideMaps(a, planner.worldKeyPoints()) == 0);
  PsmSwitches never;
  never.faces = FaceMode::Never;
  CHECK(planner.plan(streetCamera(), lamp, s.receivers, s.receivers, {}, never).status == PlanStatus::NoLightCamera);
}

TEST_CASE("psm plan: nothing in view, and a direction light gets an orthographic map") {
  PsmPlanner planner;
  const std::vector<Aabb> away{box({-1, 0, 20}, {1, 1, 22})};  // behind the eye
  CHECK(planner.plan(streetCamera(), glm::dvec4(0, 1, 0, 0), away, away, {}, {}).status == PlanStatus::NothingInView);
  const Street s;
  // A sun straight up over a camera looking horizontally: parallel to the near plane.
  const PsmPlan& p = planner.plan(streetCamera(), glm::dvec4(0, 1, 0, 0), s.receivers, s.receivers, {}, {});
  REQUIRE(p.status == PlanStatus::Ok);
  CHECK(p.light.kind == PostLightKind::Direction);
  CHECK(p.maps[0].camera.kind == LightProjection::Orthographic);
  CHECK(pointsOutsideMaps(p, planner.worldKeyPoints()) == 0);
}

TEST_CASE("psm plan: a student's steps replace the reference's") {
  const Street s;
  PsmPlanner planner;
  PsmSwitches st;
  int cones = 0, lights = 0, shifts = 0;
  st.options.steps.cone = [&](std::span<glm::dvec3> d) {
    ++cones;
    return smallestEnclosingCone(d);
  };
  st.toPostProjective = [&](const glm::dmat4& vp, const glm::dvec4& l) {
    ++lights;
    return toPostProjective(vp, l);
  };
  st.virtualShift = [&](const CameraFrustum& c, std::span<const Aabb> b) {
    ++shifts;
    return 2.0;
  };
  st.inverseProjection = false;
  const PsmPlan& p = planner.plan(streetCamera(), glm::dvec4(0, 1, 1, 0), s.receivers, s.receivers, s.behind, st);
  CHECK(cones == 1);
  CHECK(lights == 2);  // the real camera's, then the slid one's
  CHECK(shifts == 1);
  CHECK(p.shift == 2.0);
  // A visibility test calling every face hidden: the faces the light sees still get no map.
  PsmSwitches faces;
  faces.faces = FaceMode::Always;
  faces.options.steps.faceVisible = [](int, const PostProjectiveLight&) { return false; };
  const PsmPlan& f = planner.plan(streetCamera(), glm::dvec4(0.3, 1, -0.2, 0), s.receivers, s.receivers, {}, faces);
  CHECK(f.faceMask == 63u);
  CHECK(f.mapCount == hiddenFaceCount(f.light));
}

TEST_CASE("psm receivers: large objects become a coarse height map, small ones keep their box") {
  Scene scene;
  const std::uint32_t ground = scene.addMesh(makePlane(40.0f, 32, 1.0f));
  const std::uint32_t cube = scene.addMesh(makeBox(glm::vec3(2.0f), 1));
  scene.addMaterial({});
  SceneObject g;
  g.mesh = ground;
  scene.addObject(g);
  SceneObject b;
  b.mesh = cube;
  b.model[3] = glm::vec4(5, 1, 5, 1);
  scene.addObject(b);
  const auto tiles = receiverVolumes(scene, 8);  // cells of 40 / 8 = 5 m: the ground in 8 x 8 tiles
  CHECK(tiles.size() == 64 + 1);
  const auto boxes = receiverVolumes(scene, 1);
  CHECK(boxes.size() == 2);
  // Every triangle of the ground lies in some tile.
  const Mesh& m = scene.meshes[ground];
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 c =
        (m.positions[m.indices[t]] + m.positions[m.indices[t + 1]] + m.positions[m.indices[t + 2]]) / 3.0f;
    bool in = false;
    for (const Aabb& a : tiles)
      in = in || (glm::all(glm::lessThanEqual(a.min, c)) && glm::all(glm::lessThanEqual(c, a.max)));
    CHECK(in);
  }
  CHECK_THROWS_AS(receiverVolumes(scene, 1000), std::invalid_argument);
}

TEST_CASE("psm receivers: potential casters agree with lesson 03's swept-volume test for the sun") {
  const CameraFrustum cam = streetCamera();
  const Frustum f = frustumFromViewProj(cam.viewProj, cam.invViewProj);
  const shadow::ConvexVolume v = shadow::volumeFromViewProj(glm::mat4(cam.viewProj));
  std::mt19937_64 rng(test::seedFor("psm potential casters"));
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int culled = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 c(60 * u(rng), 20 * u(rng), 60 * u(rng)), e(2 + u(rng), 2 + u(rng), 2 + u(rng));
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), -1.0f, u(rng)));
    const Aabb b = box(c - e, c + e);
    const bool mine = mayShadowFrustum(b, f, glm::dvec4(-glm::dvec3(d), 0.0));
    // Lesson 03's test may keep more (float planes); it never culls what ours keeps.
    if (mine) CHECK(shadow::casterMayShadow(b, v, d));
    culled += !mine;
  }
  CHECK(culled > 50);
  // A point light inside the frustum: a box beside the frustum cannot shade it.
  CHECK_FALSE(mayShadowFrustum(box({-80, 0, -30}, {-70, 5, -20}), f, glm::dvec4(0, 2, -10, 1)));
  // A point light beside the frustum, the box between them: it can.
  CHECK(mayShadowFrustum(box({-30, 0, -22}, {-25, 5, -18}), f, glm::dvec4(-60, 2, -20, 1)));
}

TEST_CASE("psm bias: the factored texel step equals K = M^-1 (C - I) M") {
  std::mt19937_64 rng(test::seedFor("psm texel step"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    glm::dmat4 m(1.0);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] += 0.5 * u(rng);
    const glm::dvec2 size(256 + 1000 * (u(rng) + 1), 256 + 1000 * (u(rng) + 1));
    const glm::dmat4 K = texelOffsetMatrix(m, size);
    const TexelStep t = texelStepFactors(m, size);
    const glm::dvec4 p(10 * u(rng), 10 * u(rng), 10 * u(rng), 1.0);
    const glm::dvec4 a = K * p, b = t.u * glm::dot(t.r, p);
    for (int k = 0; k < 4; ++k) CHECK(a[k] == doctest::Approx(b[k]).epsilon(1e-9).scale(1e-12));
  }
}

TEST_CASE("psm shapes: the unit cube, and a frustum through infinity") {
  PostProjectiveShapes s;
  s.unitCube({1, 1, 1, 1});
  REQUIRE(s.lines().size() == 12);
  for (const auto& l : s.lines()) CHECK(glm::length(glm::dvec3(l.b - l.a)) == doctest::Approx(2.0));
  // The inverse projection (a = 0.5): its volume is |Z| >= a, so the edges joining the depth -1 and
  // +1 corners pass through infinity: their homogeneous ends have w of opposite signs.
  s.clear();
  s.frustum(glm::inverse(inverseProjection(1.0, 1.0, 0.5)), {1, 1, 1, 1});
  int throughInfinity = 0;
  for (const auto& l : s.lines()) throughInfinity += l.a.w * l.b.w < 0.0;
  CHECK(throughInfinity == 4);
  // An ordinary perspective: every corner finite on the same side.
  s.clear();
  s.frustum(glm::inverse(perspectiveGL(1.0, 1.0, 0.5, 10.0)), {1, 1, 1, 1});
  for (const auto& l : s.lines()) CHECK(l.a.w * l.b.w > 0.0);
  // A light behind: its cross, and two rays that end at infinity (w = 0).
  s.clear();
  PostProjectiveLight behind;
  behind.kind = PostLightKind::Behind;
  behind.position = {0, 0, 1.05};
  s.light(behind, {1, 0, 0, 1});
  int rays = 0;
  for (const auto& l : s.lines()) rays += l.a.w == 0.0 || l.b.w == 0.0;
  CHECK(s.lines().size() == 5);
  CHECK(rays == 2);
}

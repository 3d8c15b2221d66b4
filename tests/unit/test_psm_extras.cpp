// Unit tests for common/algorithms/psm: cube faces, bias, LiSPSM, cascades, aliasing (hand-derived values).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/aliasing.hpp"
#include "algorithms/psm/bias.hpp"
#include "algorithms/cascades.hpp"
#include "algorithms/psm/cube_faces.hpp"
#include "algorithms/psm/lispsm.hpp"

using namespace shadowlab::psm;

namespace {
PostProjectiveLight finite(glm::dvec3 p, bool front = true) {
  PostProjectiveLight l;
  l.kind = front ? PostLightKind::InFront : PostLightKind::Behind;
  l.position = p;
  return l;
}
}  // namespace

TEST_CASE("psm cube faces: counts, faces of points, lookup vector") {
  CHECK(hiddenFaceCount(finite({0, 0, 5})) == 5);
  CHECK(hiddenFaceCount(finite({5, 5, 5})) == 3);
  CHECK(hiddenFaceCount(finite({5, 5, 0})) == 4);
  CHECK(hiddenFaceCount(finite({0.1, 0.2, 0.3})) == 6);
  // From (0,0,5) the ray through (0.5, 0, 0.9) leaves through the bottom (-z) face; through
  // (0.9, 0, -0.5) it leaves through +x (it reaches x = 1 at z = -2.2/0.9... before z = -1).
  CHECK(cubeFaceOf({0.5, 0, 0.9}, finite({0, 0, 5})) == 5);
  CHECK(cubeFaceOf({0.95, 0, -0.5}, finite({0, 0, 5})) == 0);
  CHECK(cubeLookupVector({1, 2, 3}, finite({0, 0, 5})) == glm::dvec3(1, 2, -2));
}

TEST_CASE("psm cube faces: each face camera maps its face square onto the map square") {
  const PostProjectiveLight l = finite({0.3, -2.0, 4.0});
  const CubeFaceSet set = cubeFaceCameras(l, glm::dmat4(1.0), {});
  for (int f = 0; f < 6; ++f) {
    if (!set.faces[f].used) continue;
    const glm::dvec3 n = cubeFaceNormal(f);
    // The face's centre and a corner-ish point project inside [-1,1]^2 and in depth range.
    for (const glm::dvec3 t : {glm::dvec3(0), glm::dvec3(0.99, 0.99, 0.99) * (glm::dvec3(1) - glm::abs(n))}) {
      const glm::dvec3 p = n + t;
      if (cubeFaceOf(p * 0.999, l) != f) continue;
      const glm::dvec4 h = set.faces[f].camera.postToClip * glm::dvec4(p * 0.999, 1.0);
      REQUIRE(h.w > 0);
      CHECK(std::abs(h.x / h.w) <= 1.0);
      CHECK(std::abs(h.y / h.w) <= 1.0);
      CHECK(std::abs(h.z / h.w) <= 1.0);
    }
  }
}

TEST_CASE("psm cube faces: region distance of the -z face seen from (0,0,5) is 4") {
  // The part of the cube whose rays leave through z = -1 starts at the top face z = 1.
  CHECK(cubeFaceRegionMinDistance({0, 0, 5}, 5) == doctest::Approx(4.0));
  // The +x face from (0,0,5): a ray leaving through (1, y, ze) holds x = (5 - z) / (5 - ze), whose
  // least value in the cube (z = 1, ze = -1) is 4/6 = 2/3.
  CHECK(cubeFaceRegionMinDistance({0, 0, 5}, 0) == doctest::Approx(2.0 / 3.0));
  CHECK(cubeFaceRegionMinDistance({0, 0, 0.5}, 0) == 0.0);
}

TEST_CASE("psm bias: texel size with an affine map, clamping, and the constant bias it replaces") {
  glm::dmat4 M(0.5);
  M[3][3] = 1.0;
  const glm::dmat4 K = texelOffsetMatrix(M, {4, 4});
  CHECK(texelWorldSize(K, {1, 2, 3}) == doctest::Approx(std::sqrt(2.0)));
  CHECK(texelWorldSizePaper(K, {1, 2, 3}) == doctest::Approx(2.0));  // the paper squares it
  const glm::dvec3 b = biasedWorldPoint({0, 0, 0}, {0, 0, -1}, 0.1, 1.0, 1e9, 0.5);
  CHECK(b.z == doctest::Approx(-0.5));  // clamped
  const glm::dvec3 inf =
      biasedWorldPoint({0, 0, 0}, {0, 0, -1}, 0.1, 1.0, std::numeric_limits<double>::infinity(), 2.0);
  CHECK(inf.z == doctest::Approx(-2.0));
  CHECK_THROWS_AS(texelOffsetMatrix(glm::dmat4(0.0), {4, 4}), std::invalid_argument);
  CHECK_THROWS_AS(texelOffsetMatrix(M, {0, 4}), std::invalid_argument);
  CHECK_THROWS_AS(biasedWorldPoint({0, 0, 0}, {0, 0, 0}, 0.1, 1.0, 1.0), std::invalid_argument);
  // A constant NDC bias of 0.02 under the affine M (depth = z / 2) is a world shift of 0.04.
  CHECK(worldShiftOfDepthBias(M, {0, 0, 0}, {0, 0, 1}, 0.02) == doctest::Approx(0.04));
  const glm::dvec4 h = constantDepthBiasMatrix(0.02) * glm::dvec4(0, 0, 0.5, 2.0);
  CHECK(h.z / h.w == doctest::Approx(0.25 + 0.02));
  CHECK(directionFromLight({0, 0, 1, 0}, {5, 5, 5}) == glm::dvec3(0, 0, -1));
  CHECK(directionFromLight({0, 0, 2, 1}, {0, 0, 5}) == glm::dvec3(0, 0, 1));
}

TEST_CASE("cascades: the practical split scheme at lambda 0, 1 and 0.5") {
  const auto uni = shadowlab::shadow::cascadeSplits(1.0, 9.0, 2, 0.0);
  CHECK(uni == std::vector<double>{1.0, 5.0, 9.0});
  const auto lg = shadowlab::shadow::cascadeSplits(1.0, 9.0, 2, 1.0);
  CHECK(lg[1] == doctest::Approx(3.0));
  const auto mix = shadowlab::shadow::cascadeSplits(1.0, 9.0, 2, 0.5);
  CHECK(mix[1] == doctest::Approx(4.0));
  CHECK_THROWS_AS(shadowlab::shadow::cascadeSplits(0.0, 9.0, 2, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(shadowlab::shadow::cascadeSplits(1.0, 9.0, 0, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(shadowlab::shadow::cascadeSplits(1.0, 9.0, 2, 1.5), std::invalid_argument);
}

TEST_CASE("psm aliasing: closed forms at the ends of the depth range") {
  const double n = 1.0, f = 100.0;
  CHECK(perspectiveAliasing(Parameterisation::Uniform, n, n, f) == doctest::Approx(99.0));
  CHECK(perspectiveAliasing(Parameterisation::Uniform, f, n, f) == doctest::Approx(0.99));
  CHECK(perspectiveAliasing(Parameterisation::Psm, n, n, f) == doctest::Approx(0.99));
  CHECK(perspectiveAliasing(Parameterisation::Psm, f, n, f) == doctest::Approx(99.0));
  CHECK(perspectiveAliasing(Parameterisation::Logarithmic, 7.0, n, f) == doctest::Approx(std::log(100.0)));
  // LiSPSM's optimum n = zn + sqrt(zn zf) = 11 equalises both ends: 11 * 99 / 110 = 9.9.
  CHECK(perspectiveAliasing(Parameterisation::Lispsm, n, n, f) == doctest::Approx(9.9));
  CHECK(perspectiveAliasing(Parameterisation::Lispsm, f, n, f) == doctest::Approx(9.9));
  // LiSPSM with n = zn is PSM.
  CHECK(perspectiveAliasing(Parameterisation::Lispsm, 30.0, n, f, n) ==
        doctest::Approx(perspectiveAliasing(Parameterisation::Psm, 30.0, n, f)));
  // m = (dz/ds) / z: check against a numerical derivative of s(z).
  for (auto p :
       {Parameterisation::Uniform, Parameterisation::Psm, Parameterisation::Lispsm, Parameterisation::Logarithmic}) {
    const double z = 17.0, h = 1e-4;
    const double ds = shadowMapCoordinate(p, z + h, n, f) - shadowMapCoordinate(p, z - h, n, f);
    CHECK(perspectiveAliasing(p, z, n, f) == doctest::Approx(2 * h / ds / z).epsilon(1e-6));
  }
  CHECK_THROWS_AS(perspectiveAliasing(Parameterisation::Psm, 0.5, n, f), std::invalid_argument);
}

TEST_CASE("psm lispsm: n_opt and a fit that holds the body") {
  CHECK(lispsmOptimalN(1.0, 100.0, std::numbers::pi / 2) == doctest::Approx(11.0));
  CHECK(lispsmOptimalN(1.0, 100.0, std::numbers::pi / 6) == doctest::Approx(22.0));
  CHECK(std::isinf(lispsmOptimalN(1.0, 100.0, 0.0)));
  const CameraFrustum cam = makeCamera(glm::dmat4(1.0), 1.0, 1.0, 1.0, 50.0);
  const std::vector<glm::dvec3> body = {{-1, -1, -1}, {1, 1, -1}, {-20, -5, -40}, {20, 5, -40}, {0, -5, -10}};
  for (const glm::dvec3 L : {glm::dvec3(0, -1, 0), glm::dvec3(0.3, -1, 0.5), glm::dvec3(0, 0, -1)}) {
    const LispsmCamera ls = fitLispsm(cam, L, body);
    CHECK(ls.perspective == (L.x != 0.0 || L.z == 0.0));  // along the view: the uniform fallback
    for (const auto& p : body) {
      const glm::dvec4 h = ls.worldToClip * glm::dvec4(p, 1.0);
      REQUIRE(h.w > 0);
      CHECK(std::abs(h.x / h.w) <= 1 + 1e-9);
      CHECK(std::abs(h.y / h.w) <= 1 + 1e-9);
      CHECK(std::abs(h.z / h.w) <= 1 + 1e-9);
    }
  }
}

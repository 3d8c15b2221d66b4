// Filterable shadow maps' bounds (common/algorithms/moment_maps): each is exact for one occluder,
// an upper bound of the lit share for a mixture of depths, and the papers' claim that EVSM and MSM
// bleed less light than VSM where two casters overlap in the kernel.
#include <doctest/doctest.h>

#include <initializer_list>

#include "algorithms/moment_maps.hpp"

using namespace shadowlab;

namespace {
// The blurred moments of a kernel holding depth z0 on a share w0 and z1 on the rest.
glm::dvec4 mixVsm(double z0, double w0, double z1) {
  return w0 * glm::dvec4(z0, z0 * z0, 0, 0) + (1 - w0) * glm::dvec4(z1, z1 * z1, 0, 0);
}
glm::dvec4 mixMsm(double z0, double w0, double z1) {
  return w0 * soft::msmMoments(z0) + (1 - w0) * soft::msmMoments(z1);
}
glm::dvec4 mixEvsm(double z0, double w0, double z1, double cp, double cn) {
  return w0 * soft::evsmMoments(z0, cp, cn) + (1 - w0) * soft::evsmMoments(z1, cp, cn);
}
double vsmLit(const glm::dvec4& m, double t) { return soft::chebyshevUpperBound(m.x, m.y, t, 1e-6); }
constexpr double kAlpha32 = 3e-7, kAlpha16 = 3e-5;
}  // namespace

TEST_CASE("moment maps: Chebyshev's bound and the bleeding reduction") {
  CHECK(soft::chebyshevUpperBound(0.5, 0.26, 0.4, 0.0) == 1.0);                    // in front of the mean: lit
  CHECK(soft::chebyshevUpperBound(0.5, 0.26, 0.6, 0.0) == doctest::Approx(0.5));   // var 0.01, d 0.1
  CHECK(soft::chebyshevUpperBound(0.5, 0.25, 0.6, 0.01) == doctest::Approx(0.5));  // the floor
  CHECK(soft::reduceBleeding(0.6, 0.2) == doctest::Approx(0.5));
  CHECK(soft::reduceBleeding(0.1, 0.2) == 0.0);
  CHECK(soft::reduceBleeding(1.0, 0.5) == doctest::Approx(1.0));
}

TEST_CASE("moment maps: MSM's quantisation round trip, into [0, 1]") {
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
    CAPTURE(t);
    const glm::dvec4 b = soft::msmMoments(t);
    const glm::dvec4 q = soft::msmQuantise(b), back = soft::msmDequantise(q);
    for (int k = 0; k < 4; ++k) {
      CHECK(back[k] == doctest::Approx(b[k]).epsilon(1e-6));
      CHECK(q[k] >= -0.05);  // the point of the transform: room for 16-bit unsigned storage
      CHECK(q[k] <= 1.05);
    }
  }
}

TEST_CASE("moment maps: one occluder is exact for every kind") {
  const double z = 0.4;
  for (double t : {0.2, 0.38}) {  // in front: lit
    CAPTURE(t);
    CHECK(vsmLit(mixVsm(z, 1, z), t) == 1.0);
    CHECK(soft::evsmLitShare(soft::evsmMoments(z, 40, 5), t, 40, 5, true, 1e-6) == doctest::Approx(1.0).epsilon(1e-3));
    CHECK(soft::msmLitShare(soft::msmMoments(z), t, kAlpha32) == doctest::Approx(1.0).epsilon(1e-3));
  }
  for (double t : {0.45, 0.6, 0.9}) {  // behind: shadowed
    CAPTURE(t);
    CHECK(vsmLit(mixVsm(z, 1, z), t) < 0.01);
    CHECK(soft::evsmLitShare(soft::evsmMoments(z, 40, 5), t, 40, 5, true, 1e-6) < 0.01);
    CHECK(soft::msmLitShare(soft::msmMoments(z), t, kAlpha32) < 0.01);
    CHECK(soft::msmLitShare(soft::msmDequantise(soft::msmQuantise(soft::msmMoments(z))), t, kAlpha16) < 0.05);
  }
}

TEST_CASE("moment maps: two casters in one kernel: bounds of the lit share, MSM and EVSM bleed less than VSM") {
  // Half the kernel sees a caster at 0.3, half one at 0.6; the receiver is at t.
  for (const double t : {0.45, 0.7, 0.9}) {
    CAPTURE(t);
    const double truth = t < 0.6 ? 0.5 : 0.0;  // the share of the kernel not in front of t
    const double vsm = vsmLit(mixVsm(0.3, 0.5, 0.6), t);
    const double evsm2 = soft::evsmLitShare(mixEvsm(0.3, 0.5, 0.6, 40, 5), t, 40, 5, false, 1e-6);
    const double evsm4 = soft::evsmLitShare(mixEvsm(0.3, 0.5, 0.6, 40, 5), t, 40, 5, true, 1e-6);
    const double msm = soft::msmLitShare(mixMsm(0.3, 0.5, 0.6), t, kAlpha32);
    // Upper bounds: never darker than the truth (a filterable map leaks light, it does not invent shadow).
    CHECK(vsm >= truth - 1e-9);
    CHECK(evsm2 >= truth - 1e-9);
    CHECK(evsm4 >= truth - 1e-9);
    CHECK(msm >= truth - 1e-3);
    CHECK(evsm4 <= evsm2 + 1e-12);
    // The papers' claim where light bleeds (the receiver behind both casters, truly shadowed): less
    // light than VSM's bound. Between the casters EVSM2's positive warp is looser than VSM (its
    // mean is the far caster's), which the negative warp of EVSM4 repairs.
    if (truth == 0.0) {
      CHECK(evsm2 < vsm);
      CHECK(evsm4 < vsm);
      CHECK(msm < vsm);
    }
  }
}

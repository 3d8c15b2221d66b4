#pragma once
// Light Space Perspective Shadow Maps (Wimmer, Scherzer, Purgathofer 2004): the industry's
// baseline against PSM in lesson 10. A perspective frustum whose axis is the view direction
// projected perpendicular to the (directional) light, so the light stays a direction after it
// and an orthographic map along the light follows. Its free parameter is n, the distance from the
// perspective's centre to the body's near side: n_opt = (zn + sqrt(zn zf)) / sin(gamma), gamma the
// angle between view and light directions. n -> inf gives the uniform map, n = zn PSM-like.
#include <functional>
#include <span>

#include <glm/glm.hpp>

#include "algorithms/psm/conventions.hpp"

namespace shadowlab::psm {

// (zn + sqrt(zn zf)) / sin(gamma); +inf when sin(gamma) = 0 (light along the view: LiSPSM
// degenerates to the uniform map). Throws std::invalid_argument on bad zn/zf/gamma.
double lispsmOptimalN(double zNear, double zFar, double gamma);

struct LispsmCamera {
  glm::dmat4 worldToClip{1.0};  // world -> shadow-map clip (x, y: map, z: depth along the light)
  double n = 0.0;               // the n used (infinite: the uniform fallback)
  double gamma = 0.0;           // radians between the view direction and the light's direction
  bool perspective = false;     // false: the uniform (orthographic) fallback was used
};

// worldPoints: the receiver body (e.g. receiverKeyPoints). lightDirection: where light travels.
// nOverride > 0 replaces n_opt (for the comparison lesson's slider). optimalN replaces
// lispsmOptimalN(z0, z1, gamma) (a student's, impl=student); empty: the reference.
LispsmCamera fitLispsm(const CameraFrustum& camera, const glm::dvec3& lightDirection,
                       std::span<const glm::dvec3> worldPoints, DepthRange range = DepthRange::MinusOneToOne,
                       double nOverride = 0.0, const std::function<double(double, double, double)>& optimalN = {});

}  // namespace shadowlab::psm

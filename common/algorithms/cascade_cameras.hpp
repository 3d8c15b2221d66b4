#pragma once
// Cascaded shadow maps' light cameras, GL-free (common/technique/cascades renders them): the view's
// depth range [near, far] cut by the practical split scheme (psm::cascadeSplits, Zhang et al. 2006),
// and for each slice of the view frustum a directional light camera fitted to it as lesson 03 fits
// one to the whole view (fitDirectional: the receivers where the slice meets the scene's bounds, the
// casters that can shade them, texel snapping at the cascade's own texel size).
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/light_cameras.hpp"

namespace shadowlab::shadow {

// The viewer whose frustum the cascades split (its view matrix and perspective).
struct CascadeViewer {
  glm::mat4 view{1.0f};
  float fovY = 0.873f, aspect = 1.0f, nearZ = 0.1f, farZ = 200.0f;
};

struct CascadeOptions {
  int count = 4;              // 1..4 slices
  double lambda = 0.75;       // 0 uniform splits, 1 logarithmic
  double farZ = 0.0;          // > 0: the cascades end there; 0: at the deepest point of the scene in view
  DirectionalFitOptions fit;  // per cascade; fit.mapSize is each cascade's side
};

struct CascadeSet {
  std::vector<double> splits;        // count + 1 view depths, splits[0] = near
  std::vector<LightCamera> cameras;  // cascade i covers depths [splits[i], splits[i + 1]]
};

// How deep the cascades reach: the farthest corner of `bounds` in front of the viewer, clamped to
// (nearZ, farZ]; farZ when the whole box is behind the near plane.
double cascadeFar(const CascadeViewer& viewer, const Aabb& bounds);

// The slices and their light cameras for a directional light travelling along `direction`.
// Throws std::invalid_argument for count outside 1..4 and as cascadeSplits / fitDirectional do.
CascadeSet fitCascades(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& viewer,
                       const CascadeOptions& options);

}  // namespace shadowlab::shadow

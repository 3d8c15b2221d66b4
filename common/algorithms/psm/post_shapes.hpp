#pragma once
// What the post-projective view draws besides the squashed scene, GL-free: lines between
// HOMOGENEOUS points of a camera's post-projective space, so that a frustum reaching through
// infinity (fix 1's inverse projection, the original's reversed one, a light camera seen from a
// camera it is behind) is drawn as the projective figure it is. A segment from a to b is the set
// of points (1 - t) a + t b, t in [0, 1], taken projectively: with a.w and b.w of opposite signs it
// passes through the plane at infinity instead of between the two finite points; with b.w = 0 it
// is the ray from a toward b.xyz. The renderer (technique/post_projective_view) draws each line
// once as given and once negated, which covers exactly that set.
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/psm/conventions.hpp"
#include "algorithms/psm/psm_plan.hpp"

namespace shadowlab::psm {

struct HomogeneousLine {
  glm::dvec4 a, b;
  glm::vec4 colour;
};

class PostProjectiveShapes {
 public:
  void clear() { lines_.clear(); }
  void line(const glm::dvec4& a, const glm::dvec4& b, const glm::vec4& colour) { lines_.push_back({a, b, colour}); }
  void segment(const glm::dvec3& a, const glm::dvec3& b, const glm::vec4& colour) {
    line(glm::dvec4(a, 1.0), glm::dvec4(b, 1.0), colour);
  }
  void cross(const glm::dvec3& p, double size, const glm::vec4& colour);
  // The 12 edges of the volume that `clipToPost` maps the clip cube [-1,1]^3 onto: the NDC corners
  // taken through it homogeneously (never divided), so a volume through infinity stays one.
  void frustum(const glm::dmat4& clipToPost, const glm::vec4& colour);
  void unitCube(const glm::vec4& colour) { frustum(glm::dmat4(1.0), colour); }
  // A cone from apex along unit axis: 8 rays of `length` and the circle where they end.
  void cone(const glm::dvec3& apex, const glm::dvec3& axis, double halfAngle, double length, const glm::vec4& colour);
  // The light where it lands: a cross at a finite position; for a light behind, also the ray that
  // leaves it away from the cube and comes back from infinity on the far side; for a direction,
  // parallel rays through the cube along -direction.
  void light(const PostProjectiveLight& light, const glm::vec4& colour);
  // A world-space light camera (worldToClip) seen in the post-projective space of viewProj.
  void worldFrustum(const glm::dmat4& viewProj, const glm::dmat4& worldToClip, const glm::vec4& colour) {
    frustum(viewProj * glm::inverse(worldToClip), colour);
  }
  const std::vector<HomogeneousLine>& lines() const { return lines_; }

 private:
  std::vector<HomogeneousLine> lines_;
};

// Colours the views share (light camera, cone, key points, faces, the slid cube...).
struct PostProjectivePalette {
  glm::vec4 cube{0.95f, 0.95f, 0.95f, 1.0f};
  glm::vec4 realCube{1.0f, 0.85f, 0.2f, 1.0f};  // the real camera's cube inside the virtual one
  glm::vec4 light{1.0f, 0.9f, 0.3f, 1.0f};
  glm::vec4 lightBehind{1.0f, 0.35f, 0.3f, 1.0f};
  glm::vec4 map{0.3f, 0.85f, 1.0f, 1.0f};
  glm::vec4 cone{0.75f, 0.5f, 1.0f, 1.0f};
  glm::vec4 keyPoint{0.4f, 1.0f, 0.5f, 1.0f};
};

// What a PSM plan adds in its own post-projective space (the view draws the unit cube and the light
// itself): the real camera's cube inside the slid one, each map's light frustum (through infinity
// for the inverse and reversed projections), the cone, and the key points (at most maxPoints).
void describePlan(const PsmPlan& plan, const CameraFrustum& realCamera, std::span<const glm::dvec3> postKeyPoints,
                  PostProjectiveShapes& out, std::size_t maxPoints = 4096, const PostProjectivePalette& palette = {});

}  // namespace shadowlab::psm

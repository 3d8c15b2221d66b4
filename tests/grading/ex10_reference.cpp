// Reference for lesson 10's exercises: forwards to common/algorithms (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex10 {

std::vector<double> practicalSplits(double zNear, double zFar, int count, double lambda) {
  return shadow::cascadeSplits(zNear, zFar, count, lambda);
}

shadow::TexelSnap snapToTexels(const glm::vec2& centre, const glm::vec2& half, int mapSize) {
  return shadow::snapToTexels(centre, half, mapSize);
}

shadow::CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band) {
  return shadow::cascadeAt(splits, depth, band);
}

}  // namespace shadowlab::ex10

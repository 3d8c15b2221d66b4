// Lesson 10: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=10   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex10 {

// EXERCISE 10.1
std::vector<double> practicalSplits(double zNear, double zFar, int count, double lambda) {
  SHADOWLAB_STUB("10.1");  // delete this line when you write the exercise
  // TODO: count + 1 distances, lambda * log + (1 - lambda) * uniform, the ends exact
  return {};
}

// EXERCISE 10.2
shadow::TexelSnap snapToTexels(const glm::vec2& centre, const glm::vec2& half, int mapSize) {
  SHADOWLAB_STUB("10.2");  // delete this line when you write the exercise
  // TODO: square and grow by two texels, round h up to its step, the centre to whole texels
  return shadow::TexelSnap{};
}

// EXERCISE 10.3
shadow::CascadeBlend cascadeAt(std::span<const double> splits, double depth, double band) {
  SHADOWLAB_STUB("10.3");  // delete this line when you write the exercise
  // TODO: the first cascade whose far split is >= depth, then the weight in its band
  return shadow::CascadeBlend{};
}

}  // namespace shadowlab::ex10

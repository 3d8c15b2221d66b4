// Lesson 07: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=07   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex07 {

// EXERCISE 07.1
hybrid::BlockMerge mergeBlock(const std::array<float, 4>& d, float eps0) {
  SHADOWLAB_STUB("07.1");  // delete this line when you write the exercise
  // TODO: the mean, then |m - Dn| <= eps0 * Dn for all four; never merge over a negative child
  return hybrid::BlockMerge{};
}

// EXERCISE 07.2
hybrid::MergeGrid sweepLevel(const hybrid::MergeGrid& children, float eps0) {
  SHADOWLAB_STUB("07.2");  // delete this line when you write the exercise
  // TODO: (size + 1) / 2 a side; each texel's block through mergeBlock, kInternal when kept or cut
  return hybrid::MergeGrid{};
}

// EXERCISE 07.3
hybrid::Descent descend(const hybrid::HybridMap& map, int sx, int sy) {
  SHADOWLAB_STUB("07.3");  // delete this line when you write the exercise
  // TODO: the root word, then down the records while it is a pointer
  return hybrid::Descent{};
}

// EXERCISE 07.4
float linearDepth(float windowDepth, float nearZ, float farZ) {
  SHADOWLAB_STUB("07.4");  // delete this line when you write the exercise
  // TODO: 2 n f / ((f + n) - (2 d - 1)(f - n))
  return 0.0f;
}

}  // namespace shadowlab::ex07

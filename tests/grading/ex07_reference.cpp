// The reference for lesson 07's graders: forwards to common/algorithms/hybrid_map (never a copy).
#include "exercises.hpp"

namespace shadowlab::ex07 {
namespace {
hybrid::MergeRule windowRule(float eps0) {
  hybrid::MergeRule rule;
  rule.criterion = hybrid::Criterion::Window;
  rule.eps0 = eps0;
  return rule;
}
}  // namespace

hybrid::BlockMerge mergeBlock(const std::array<float, 4>& d, float eps0) {
  return hybrid::mergeBlock(d, windowRule(eps0), 1);
}
hybrid::MergeGrid sweepLevel(const hybrid::MergeGrid& children, float eps0) {
  return hybrid::sweepLevel(children, windowRule(eps0), 1);
}
hybrid::Descent descend(const hybrid::HybridMap& map, int sx, int sy) { return hybrid::descend(map, sx, sy); }
float linearDepth(float d, float nearZ, float farZ) { return hybrid::linearDepth(d, {true, nearZ, farZ, 0.0f}); }
}  // namespace shadowlab::ex07

#include "technique/no_shadows.hpp"

namespace shadowlab::tech {

// Nothing to render: no map, no volume. The stats say so (and that nothing is culled).
void NoShadows::render(const ShadowContext&) {
  stats_ = {};
  stats_.culls = false;
}

}  // namespace shadowlab::tech

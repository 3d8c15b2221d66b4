#include "showdown_techniques.hpp"

#include "03_shadow_quality/uniform_maps.hpp"
#include "04_shadow_volumes/stencil_volumes.hpp"
#include "05_soft_shadows/soft_techniques.hpp"
#include "07_hybrid_maps/hybrid_maps.hpp"
#include "08_psm/psm.hpp"
#include "09_psm_fixes/lispsm.hpp"
#include "cascades.hpp"
#include "sdsm.hpp"
#include "technique/no_shadows.hpp"

namespace shadowlab::tech {

std::vector<TechniqueEntry> showdownTechniques() {
  std::vector<TechniqueEntry> all = {
      entryOf<UniformShadowMaps>("uniform", "uniform"),       // lesson 03's fitted maps
      entryOf<PerspectiveShadowMaps>("psm", "psm"),           // lessons 08-09: PSM with the paper's fixes
      entryOf<LightSpacePsm>("lispsm", "lispsm"),             // lesson 09's comparison
      entryOf<CascadedShadowMaps>("csm", "csm"),              // what engines ship: this lesson's baseline
      entryOf<SampleDistributionShadowMaps>("sdsm", "sdsm"),  // the cascades split over the depths on screen
      entryOf<HybridShadowMaps>("hybrid", "hybrid"),          // lesson 07's hybrid-resolution maps
      entryOf<StencilVolumes>("volumes", "volumes"),          // lesson 04's stencil volumes
  };
  for (TechniqueEntry& soft : softTechniques()) all.push_back(std::move(soft));
  all.push_back(entryOf<NoShadows>("none", "none"));  // V = 1: every shadowed pixel a leak
  return all;
}

}  // namespace shadowlab::tech

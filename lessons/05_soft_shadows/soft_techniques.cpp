#include "soft_techniques.hpp"

#include "filterable_maps.hpp"
#include "light_mesh.hpp"
#include "many_lights.hpp"
#include "pcss.hpp"
#include "single_sample.hpp"

namespace shadowlab::tech {

std::vector<TechniqueEntry> softTechniques() {
  return {
      entryOf<ManyLights>("many", "soft_many"),         // N point lights on the sphere, a map each, averaged
      entryOf<PcssShadows>("pcf", "soft_pcf", false),   // one map from the centre, a fixed kernel: the baseline
      entryOf<PcssShadows>("pcss", "soft_pcss", true),  // blocker search, then a filter as wide as the penumbra
      entryOf<SingleSampleSoft>("parker", "soft_parker", SingleSampleSoft::Kind::Parker),  // an outer hull
      entryOf<SingleSampleSoft>("haines", "soft_haines", SingleSampleSoft::Kind::Haines),  // plateaus on a plane
      entryOf<LightMesh>("mesh", "soft_mesh"),                                      // visibility baked on a 3D grid
      entryOf<FilterableMaps>("vsm", "soft_vsm", FilterableMaps::Kind::Vsm),        // moments, Chebyshev
      entryOf<FilterableMaps>("esm", "soft_esm", FilterableMaps::Kind::Esm),        // exp(c d), filtered
      entryOf<FilterableMaps>("evsm2", "soft_evsm2", FilterableMaps::Kind::Evsm2),  // VSM of exp(c+ t')
      entryOf<FilterableMaps>("evsm4", "soft_evsm4", FilterableMaps::Kind::Evsm4),  // and of -exp(-c- t')
      entryOf<FilterableMaps>("msm", "soft_msm", FilterableMaps::Kind::Msm),        // four moments, Hamburger
  };
}

}  // namespace shadowlab::tech

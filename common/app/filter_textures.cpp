#include "app/filter_textures.hpp"

#include "algorithms/texture_sampling.hpp"
#include "core/paths.hpp"

namespace shadowlab {

void FilterTextures::loadNormalMap(const std::string& label) {
  normalMap = gl::uploadMipChain(
      sampling::buildMipChain(sampling::toFloat(loadImage(textureRoot() + "/bricks_normal.png"))), label);
}

void FilterTextures::update(const std::string& name, int volumeSide, const std::string& prefix) {
  if (name == built_ && volumeSide == builtVolume_) return;
  built_ = name;
  builtVolume_ = volumeSide;
  const ImageF base = name == "zone_plate" ? sampling::makeZonePlate(512)
                      : name == "volume"   ? sampling::makeZonePlate(256)
                                           : sampling::toFloat(loadImage(textureRoot() + "/" + name + ".png"));
  texture = gl::uploadFilterTexture(base, prefix + (name == "zone_plate" ? " texture zone plate" : " texture file"));
  if (name == "volume")
    volume = gl::uploadVolume(volumeSide, sampling::makeShellVolume(volumeSide),
                              prefix + " volume " + std::to_string(volumeSide) + "^3");
}

}  // namespace shadowlab

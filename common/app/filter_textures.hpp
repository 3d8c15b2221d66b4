#pragma once
// The textures a filtering lesson (lesson 06) samples, each built once on the CPU and uploaded the
// same way (gl::uploadFilterTexture: the mip chain on both sides and its RIP atlas): a PNG under
// textures/, a zone plate, or a 3D texture of nested density shells (a stand-in tomogram, drawn as
// a slice; a smaller zone plate stands in for it in the 2D readouts); and the normal map that
// matches the bricks.
#include <string>

#include "gl/texture_modes.hpp"

namespace shadowlab {

class FilterTextures {
 public:
  // textures/bricks_normal.png with its mip chain (call once the context is current).
  void loadNormalMap(const std::string& label);
  // Builds `name` ("zone_plate", "volume", or NAME for textures/NAME.png) and, for "volume", a
  // volumeSide^3 3D texture; nothing when both are those of the last call. Labels start with
  // `prefix` ("06"). Throws naming a file that cannot be read.
  void update(const std::string& name, int volumeSide, const std::string& prefix);

  gl::FilterTexture texture;  // what the 2D samplers read
  gl::Texture volume;         // the last 3D texture built (kept while another texture is chosen)
  gl::Texture normalMap;

 private:
  std::string built_;
  int builtVolume_ = -1;
};

}  // namespace shadowlab

#pragma once
// Procedural textures for the course, deterministic: tools/gen_textures writes them to textures/
// and a unit test proves the committed PNGs are exactly what this code produces. Only IEEE basic
// operations and sqrt are used (no sin, pow, exp), so other platforms reproduce them bit for bit.
// All of them tile, except leaves.png, text.png and fence.png, which are used on cards.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.hpp"

namespace shadowlab {

// RGB checkerboard of `cells` x `cells` squares, `a` in the top-left one.
Image8 makeCheckerTexture(int size, int cells, glm::u8vec3 a, glm::u8vec3 b);
// RGB running-bond bricks with mortar: 16 rows of 8 bricks, tiling.
Image8 makeBricksTexture(int size, std::uint64_t seed);
// Tangent-space normal map matching makeBricksTexture (mortar grooves, bevelled edges, surface
// grain). RGB = (n * 0.5 + 0.5) * 255 with x along +u (image right), y along +v (image DOWN, the
// toolkit's uv convention where v = 0 is the top row) and z out of the surface.
Image8 makeBricksNormalTexture(int size, std::uint64_t seed);
// RGBA leaf silhouettes on a transparent background; edges anti-aliased in alpha, transparent
// texels carry leaf colour so filtering does not darken the rims.
Image8 makeLeavesTexture(int size, std::uint64_t seed);
// RGB grass and dirt patches from tiling fBm, with fine speckle.
Image8 makeGroundTexture(int size, std::uint64_t seed);
// RGB "text": rows of small dark glyph-like marks on paper, fine enough to alias when minified.
Image8 makeTextTexture(int size, std::uint64_t seed);
// RGBA picket fence: pointed pickets on two rails, transparent gaps (alpha-tested cards).
Image8 makeFenceTexture(int size);

// Every course texture with its file name under textures/: checker.png, checker_fine.png,
// bricks.png, bricks_normal.png, leaves.png, ground.png, text.png, fence.png.
std::vector<std::pair<std::string, Image8>> generateCourseTextures();

}  // namespace shadowlab

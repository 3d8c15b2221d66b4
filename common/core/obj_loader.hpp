#pragma once
// Wavefront OBJ files into a Mesh. Polygons are triangulated (convex ones and concave quads; any
// other concave polygon is an error naming its line), missing normals are computed (smooth,
// area-weighted over the file's shared positions), missing uvs are 0. OBJ's v axis points up from
// the image's bottom row; it is flipped (v' = 1 - v) to the toolkit's convention where v = 0
// samples image row 0, the top. Materials (mtllib) are ignored: scenes set their own.
//
// One parser reads every statement (it was a validating pre-scan before tinyobjloader, whose own
// number parser disagreed with it: "0e999999" became NaN, "+-5" 0, "1e39" inf). Numbers are
// decimal floats with at most one sign, finite and within a float's range; '#' starts a comment
// anywhere a token starts.
#include <string>

#include "core/mesh.hpp"

namespace shadowlab {

// Throws std::runtime_error naming the file when it cannot be read, has no faces, or holds a
// statement the loader does not understand; syntax errors also name the line ("line 7: ...").
// Never crashes on garbage.
Mesh loadObj(const std::string& path);
// The same on the file's text; errors are "line N: ..." (or "no faces") without the file name.
Mesh parseObj(const std::string& text);

}  // namespace shadowlab

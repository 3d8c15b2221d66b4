#pragma once
// Wavefront OBJ files into a Mesh, through tinyobjloader. Polygons are triangulated, missing
// normals are computed (smooth, area-weighted over the file's shared positions), missing uvs are
// 0. OBJ's v axis points up from the image's bottom row; it is flipped (v' = 1 - v) to the
// toolkit's convention where v = 0 samples image row 0, the top. Materials (mtllib) are ignored:
// scenes set their own.
#include <string>

#include "core/mesh.hpp"

namespace shadowlab {

// Throws std::runtime_error naming the file when it cannot be read, has no faces, or holds a
// statement the loader does not understand; syntax errors also name the line ("line 7: ...").
// Never crashes on garbage: every line is validated before tinyobjloader sees the text.
Mesh loadObj(const std::string& path);

}  // namespace shadowlab

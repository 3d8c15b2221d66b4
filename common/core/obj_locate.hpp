#pragma once
// Which line of a refused OBJ file is at fault, for core/model_file's messages:
//   model 'FILE': line N: reason (valid: ...)
//
// Assimp 5.2.5 is the one OBJ parser: it alone decides whether a file loads (two parsers that
// disagreed about what loads was the bug this replaced). This scanner never refuses a file. It runs
// only after a file has been refused, by Assimp or by core/model_file on what Assimp produced, and
// reads the text again to find the line that explains the refusal. It knows the statements the
// toolkit relies on (v, vt, vn, f, l) and the ways Assimp 5.2.5 refuses or drops them:
//   a coordinate that is not a number Assimp reads ("abc", "+-5", ".5", "nan"): Assimp drops the
//     vertex (the faces after it then index past the vertices) or refuses the file
//   a coordinate beyond a float's range (1e39, or an exponent over 38 as in 0e999999, which
//     Assimp's reader turns into NaN), or a w of 0 or one that divides a coordinate to infinity
//   the wrong number of coordinates (v: 3, 4 with w, or 6 with a colour; vt: 2 or 3; vn: 3)
//   a face (f) with fewer than 3 vertices or a line (l) with fewer than 2, a vertex index that is
//     not a whole number, is 0, or reaches past the vertices (v/vt/vn: only v is checked: Assimp
//     ignores uv and normal indices it cannot resolve), a comment after a face's indices (Assimp
//     refuses it), a statement whose keyword starts with f but is not f ("foo": read as a face)
//   an indented statement (Assimp skips lines that start with a space or a tab)
//   a polygon whose outline crosses itself (core/polygon), for that refusal only
// When no line explains the refusal, nothing is found and the message stays the loader's own.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace shadowlab {

// What the loader refused, so the scanner looks for the matching line.
enum class ObjFault {
  any,                // Assimp refused the file: the first line at fault of any kind
  nonFinitePosition,  // a vertex position came out NaN or infinite
  nonFiniteUv,        // a uv came out NaN or infinite
  nonFiniteNormal,    // a normal from the file came out NaN or infinite
  vertexIndex,        // a face indexes past its mesh's vertices
  selfCrossing,       // a polygon's outline crosses itself
};

struct ObjLine {
  std::size_t line = 0;  // 1-based
  std::string reason;    // one line, ending with "(valid: ...)"
};

std::optional<ObjLine> locateObjFault(std::string_view text, ObjFault fault);

}  // namespace shadowlab

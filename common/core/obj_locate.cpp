#include "core/obj_locate.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "core/polygon.hpp"

namespace shadowlab {
namespace {

// One statement: its keyword and arguments (the words before any '#').
struct Statement {
  std::size_t line = 0;
  std::string_view keyword;
  std::vector<std::string_view> args;
  bool comment = false;   // a '#' on the line
  bool indented = false;  // starts with a space or a tab
};

// What kind of fault a finding is: which refusal it explains.
enum class Kind { syntax, positionRange, uvRange, normalRange, vertexIndex, crossing };

struct Finding {
  Kind kind;
  std::string reason;
};

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
std::string numbers(std::size_t n) { return std::to_string(n) + (n == 1 ? " number" : " numbers"); }
std::string quoted(std::string_view t) { return "'" + std::string(t.substr(0, 40)) + (t.size() > 40 ? "...'" : "'"); }

Statement parseLine(std::string_view text, std::size_t line) {
  Statement s;
  s.line = line;
  s.indented = !text.empty() && (text[0] == ' ' || text[0] == '\t');
  const std::size_t hash = text.find('#');
  s.comment = hash != std::string_view::npos;
  text = text.substr(0, hash);
  for (std::size_t i = 0; i < text.size();) {
    while (i < text.size() && blank(text[i])) ++i;
    std::size_t j = i;
    while (j < text.size() && !blank(text[j])) ++j;
    if (j > i) (s.keyword.empty() ? s.keyword : s.args.emplace_back()) = text.substr(i, j - i);
    i = j;
  }
  return s;
}

// A number as Assimp 5.2.5 reads one: an optional sign, digits, an optional fraction and exponent.
// `exponent` gets the written exponent (saturated), which Assimp's reader applies in float.
bool assimpNumber(std::string_view t, long& exponent) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const std::size_t first = i;
  while (i < t.size() && digit(t[i])) ++i;
  if (i == first) return false;
  if (i < t.size() && t[i] == '.')
    for (++i; i < t.size() && digit(t[i]);) ++i;
  exponent = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    const bool negative = i < t.size() && t[i] == '-';
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t start = i;
    for (; i < t.size() && digit(t[i]); ++i) exponent = std::min(exponent * 10 + (t[i] - '0'), 100000L);
    if (i == start) return false;
    if (negative) exponent = -exponent;
  }
  return i == t.size();
}

// "nan", "inf", "-Infinity", ...: Assimp reads them as such.
bool notFinite(std::string_view t) {
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.remove_prefix(1);
  std::string word(t.substr(0, 3));
  for (char& c : word) c = char(std::tolower(static_cast<unsigned char>(c)));
  return word == "nan" || word == "inf";
}

constexpr const char* kRange = " is beyond a float's range (valid: magnitudes up to 3.4e38, exponents up to 38)";

// The coordinates of a v, vt or vn statement, or what is wrong with them.
std::optional<Finding> readNumbers(const Statement& s, Kind range, std::vector<double>& values) {
  values.clear();
  for (std::string_view t : s.args) {
    long exponent = 0;
    if (notFinite(t))
      return Finding{range, quoted(t) + " is not a finite number (valid: finite numbers such as 2 or -0.5)"};
    if (!assimpNumber(t, exponent))
      return Finding{Kind::syntax,
                     quoted(t) + " is not a number (valid: numbers such as 2, -0.5 or 1.5e-3, a digit first)"};
    const double value = std::strtod(std::string(t).c_str(), nullptr);
    if (exponent > 38 || !(std::fabs(value) <= FLT_MAX)) return Finding{range, quoted(t) + kRange};
    values.push_back(value);
  }
  return std::nullopt;
}

std::optional<Finding> checkVertex(const Statement& s, std::vector<glm::vec3>& positions) {
  std::vector<double> v;
  positions.emplace_back(0.0f);
  if (auto bad = readNumbers(s, Kind::positionRange, v)) return bad;
  const std::size_t n = v.size();
  if (n != 3 && n != 4 && n != 6)
    return Finding{Kind::syntax, "v with " + numbers(n) + " (valid: v x y z, v x y z w, or v x y z r g b)"};
  if (n == 4) {
    if (v[3] == 0.0) return Finding{Kind::syntax, "w is 0 (valid: a w other than 0: it divides x, y and z)"};
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(v[k] / v[3]) <= FLT_MAX))
        return Finding{Kind::positionRange, "dividing " + std::string(s.args[k]) + " by w = " + std::string(s.args[3]) +
                                                " goes beyond a float's range (valid: "
                                                "coordinates divided by w of magnitudes up to 3.4e38)"};
  }
  positions.back() = glm::vec3(float(v[0]), float(v[1]), float(v[2])) / float(n == 4 ? v[3] : 1.0);
  return std::nullopt;
}

std::optional<Finding> checkTexcoordOrNormal(const Statement& s) {
  const bool uv = s.keyword == "vt";
  std::vector<double> v;
  if (auto bad = readNumbers(s, uv ? Kind::uvRange : Kind::normalRange, v)) return bad;
  if (uv && (v.size() < 2 || v.size() > 3))
    return Finding{Kind::syntax, "vt with " + numbers(v.size()) + " (valid: vt u v, or vt u v w)"};
  if (!uv && v.size() < 3) return Finding{Kind::syntax, "vn with " + numbers(v.size()) + " (valid: vn x y z)"};
  return std::nullopt;
}

// A whole number as Assimp reads a face index: an optional sign and digits, saturated.
bool faceIndex(std::string_view t, long long& value) {
  std::size_t i = t.empty() || (t[0] != '-' && t[0] != '+') ? 0 : 1;
  if (i == t.size()) return false;
  value = 0;
  for (; i < t.size(); ++i) {
    if (!digit(t[i])) return false;
    value = std::min(value * 10 + (t[i] - '0'), 1'000'000'000'000LL);
  }
  if (t[0] == '-') value = -value;
  return true;
}

// One corner of a face ("v", "v/vt", "v//vn", "v/vt/vn"): its 0-based vertex, or what is wrong.
std::optional<Finding> checkCorner(std::string_view t, std::size_t total, std::size_t sofar, std::size_t& vertex) {
  const std::string range = total == 0 ? "v statements first: the file has none"
                                       : "1 to " + std::to_string(total) + ", or -1 to -" + std::to_string(sofar) +
                                             " counting back from the last vertex so far";
  std::string_view parts[3];
  std::size_t count = 0;
  for (std::size_t start = 0;; ++count) {
    const std::size_t slash = t.find('/', start);
    if (count == 3)
      return Finding{Kind::syntax, quoted(t) + " is not a face corner (valid: v, v/vt, v//vn or v/vt/vn)"};
    parts[count] = t.substr(start, slash == std::string_view::npos ? slash : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  for (std::size_t k = 1; k <= count && k < 3; ++k) {
    long long index = 0;
    if (!parts[k].empty() && (!faceIndex(parts[k], index) || index == 0))
      return Finding{Kind::syntax, quoted(parts[k]) + (k == 1 ? " is not a uv index" : " is not a normal index") +
                                       " (valid: whole numbers other than 0, or nothing, in " + quoted(t) + ")"};
  }
  long long index = 0;
  if (!faceIndex(parts[0], index))
    return Finding{Kind::syntax, quoted(parts[0]) + " is not a vertex index (valid: whole numbers, " + range + ")"};
  if (index == 0) return Finding{Kind::syntax, "vertex index 0: OBJ counts from 1 (valid: " + range + ")"};
  if (index > 0 && std::size_t(index) > total)
    return Finding{Kind::vertexIndex, "vertex index " + std::to_string(index) + " is past the file's " +
                                          std::to_string(total) + " vertices (valid: " + range + ")"};
  if (index < 0 && std::size_t(-index) > sofar)
    return Finding{Kind::vertexIndex, "vertex index " + std::to_string(index) + " reaches before the first vertex" +
                                          " (valid: " + range + ")"};
  vertex = index > 0 ? std::size_t(index - 1) : sofar - std::size_t(-index);
  return std::nullopt;
}

// A face's corners; with `crossings`, its outline too (only that refusal needs the triangulation).
std::optional<Finding> checkFace(const Statement& s, std::size_t total, const std::vector<glm::vec3>& positions,
                                 bool crossings) {
  const bool face = s.keyword == "f";
  if (face && s.comment)
    return Finding{Kind::syntax,
                   "a comment after a face's corners (valid: the comment on a line of its own: "
                   "Assimp 5.2.5 refuses '#' on a face line)"};
  const std::size_t minimum = face ? 3 : 2;
  if (s.args.size() < minimum)
    return Finding{Kind::syntax, std::string(face ? "a face" : "a line") + " with " + std::to_string(s.args.size()) +
                                     (s.args.size() == 1 ? " corner" : " corners") +
                                     (face ? " (valid: f with 3 or more corners, l for lines, p for points)"
                                           : " (valid: l with 2 or more corners)")};
  std::vector<glm::vec3> corners;
  for (std::string_view t : s.args) {
    std::size_t vertex = 0;
    if (auto bad = checkCorner(t, total, positions.size(), vertex)) return bad;
    if (vertex < positions.size()) corners.push_back(positions[vertex]);
  }
  if (crossings && face && corners.size() == s.args.size() && corners.size() > 3) try {
      triangulatePolygon(corners);
    } catch (const std::invalid_argument& e) {
      return Finding{Kind::crossing,
                     std::string(e.what()) + " (valid: simple polygons, whose edges meet only at their corners)"};
    }
  return std::nullopt;
}

// What is wrong with one statement, if anything; positions grows with each v.
std::optional<Finding> checkStatement(const Statement& s, std::size_t total, std::vector<glm::vec3>& positions,
                                      bool crossings) {
  static const char* const known[] = {"v", "vt", "vn", "vp", "f", "l", "p", "o", "g", "s", "usemtl", "mtllib"};
  const std::string_view k = s.keyword;
  if (k.empty()) return std::nullopt;
  if (s.indented) {
    for (const char* word : known)
      if (k == word)
        return Finding{Kind::syntax, "'" + std::string(k) +
                                         "' is indented (valid: statements that start the line: "
                                         "Assimp 5.2.5 skips lines that begin with a space or tab)"};
    return std::nullopt;
  }
  if (k == "v") return checkVertex(s, positions);
  if (k == "vt" || k == "vn") return checkTexcoordOrNormal(s);
  if (k == "f" || k == "l") return checkFace(s, total, positions, crossings);
  if (k[0] == 'f')
    return Finding{Kind::syntax, "unknown statement " + quoted(k) +
                                     " (valid: v, vt, vn, f, l, p, o, g, s, usemtl, "
                                     "mtllib, #: Assimp reads a word starting with f as a face)"};
  return std::nullopt;
}

bool explains(Kind kind, ObjFault fault) {
  switch (fault) {
    case ObjFault::any: return kind != Kind::crossing;
    case ObjFault::nonFinitePosition: return kind == Kind::positionRange;
    case ObjFault::nonFiniteUv: return kind == Kind::uvRange;
    case ObjFault::nonFiniteNormal: return kind == Kind::normalRange;
    case ObjFault::vertexIndex: return kind == Kind::vertexIndex;
    case ObjFault::selfCrossing: return kind == Kind::crossing;
  }
  return false;
}

template <typename F>
void forEachLine(std::string_view text, F&& f) {
  std::size_t line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (!f(parseLine(text.substr(start, end - start), line))) return;
    start = end + 1;
  }
}

}  // namespace

std::optional<ObjLine> locateObjFault(std::string_view text, ObjFault fault) {
  std::size_t total = 0;  // v statements in the file: positive indices may reach any of them
  forEachLine(text, [&](const Statement& s) {
    total += !s.indented && s.keyword == "v";
    return true;
  });
  std::vector<glm::vec3> positions;
  std::optional<ObjLine> found;
  forEachLine(text, [&](const Statement& s) {
    const std::optional<Finding> bad = checkStatement(s, total, positions, fault == ObjFault::selfCrossing);
    if (bad && explains(bad->kind, fault)) found = ObjLine{s.line, bad->reason};
    return !found;
  });
  return found;
}

}  // namespace shadowlab

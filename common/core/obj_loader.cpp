#include "core/obj_loader.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace shadowlab {

namespace {

struct ObjError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the file says, parsed once: every number is read here and only here.
struct ObjData {
  struct Corner {
    int v = -1, vt = -1, vn = -1;  // 0-based; -1: not given
  };
  struct Face {
    std::size_t first = 0, count = 0, line = 0;  // corners[first, first + count)
  };
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> texcoords;
  std::vector<Corner> corners;
  std::vector<Face> faces;
};

// Whitespace-separated tokens up to a comment: '#' starts one anywhere ("v 0 0 0 # note" is a
// vertex; names are ignored, so "usemtl red#2" losing "#2" changes nothing).
std::vector<std::string_view> tokens(std::string_view line) {
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A decimal number that is a finite float: one optional sign ("+1.0" from some exporters, never
// "+-5"), no inf or NaN, nothing past a float's range (1e39 would be inf on the GPU).
enum class Number { Ok, NotANumber, OutOfRange };
Number parseFloat(std::string_view text, float& out) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) return Number::NotANumber;
  }
  if (text.empty()) return Number::NotANumber;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (end != text.data() + text.size()) return Number::NotANumber;
  if (ec == std::errc::result_out_of_range) return Number::OutOfRange;
  if (ec != std::errc() || !std::isfinite(out)) return Number::NotANumber;
  return Number::Ok;
}

bool parseIndex(std::string_view text, long long& out) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return false;
  }
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

// Statements of the OBJ format that carry nothing a triangle mesh needs: accepted and skipped.
const std::unordered_set<std::string_view>& ignoredStatements() {
  static const std::unordered_set<std::string_view> names = {
      "o",     "g",        "s",        "mg",         "usemtl",    "mtllib", "usemap", "maplib", "lod",
      "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "cstype", "deg",    "bmat",   "step",
      "curv",  "curv2",    "surf",     "parm",       "trim",      "hole",   "scrv",   "sp",     "end",
      "con",   "ctech",    "stech",    "call",       "csh",       "vw",     "t"};
  return names;
}

class Parser {
 public:
  ObjData run(const std::string& text) {
    std::size_t pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + pos, end - pos);
      pos = end + 1;
      ++line_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      statement(line);
    }
    return std::move(data_);
  }

 private:
  ObjError fail(const std::string& why) const { return ObjError("line " + std::to_string(line_) + ": " + why); }

  void statement(std::string_view line) {
    for (char c : line)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
        throw fail("binary data (control character " + std::to_string(int(static_cast<unsigned char>(c))) + ")");
    tok_ = tokens(line);
    if (tok_.empty()) return;
    const std::string_view keyword = tok_[0];
    if (keyword == "v") {
      const std::vector<float> n = numbers(3, 7, "vertex");  // x y z [w] or x y z r g b
      data_.positions.emplace_back(n[0], n[1], n[2]);
    } else if (keyword == "vt") {
      const std::vector<float> n = numbers(1, 3, "texture coordinate");
      data_.texcoords.emplace_back(n[0], n.size() > 1 ? n[1] : 0.0f);
    } else if (keyword == "vn") {
      const std::vector<float> n = numbers(3, 3, "normal");
      data_.normals.emplace_back(n[0], n[1], n[2]);
    } else if (keyword == "f") {
      if (tok_.size() < 4) throw fail("a face needs at least 3 corners, got " + std::to_string(tok_.size() - 1));
      data_.faces.push_back({data_.corners.size(), tok_.size() - 1, line_});
      for (std::size_t i = 1; i < tok_.size(); ++i) data_.corners.push_back(corner(tok_[i], "face"));
    } else if (keyword == "vp") {
      numbers(1, 3, "parameter vertex");
    } else if (keyword == "l" || keyword == "p") {
      for (std::size_t i = 1; i < tok_.size(); ++i) corner(tok_[i], keyword == "l" ? "line" : "point");
    } else if (!ignoredStatements().count(keyword)) {
      const std::string shown = keyword.size() > 24 ? std::string(keyword.substr(0, 24)) + "..." : std::string(keyword);
      throw fail("unknown statement '" + shown + "'");
    }
  }

  std::vector<float> numbers(std::size_t minCount, std::size_t maxCount, const char* what) const {
    const std::size_t n = tok_.size() - 1;
    if (n < minCount || n > maxCount)
      throw fail(std::string(what) + " needs " + std::to_string(minCount) +
                 (maxCount != minCount ? " to " + std::to_string(maxCount) : std::string()) + " numbers, got " +
                 std::to_string(n));
    std::vector<float> out(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Number r = parseFloat(tok_[i + 1], out[i]);
      if (r == Number::OutOfRange)
        throw fail("'" + std::string(tok_[i + 1]) + "' is outside a float's range in " + what);
      if (r != Number::Ok) throw fail("'" + std::string(tok_[i + 1]) + "' is not a finite number in " + what);
    }
    return out;
  }

  // One corner of a face, line or point: v, v/vt, v//vn or v/vt/vn; negative is relative.
  ObjData::Corner corner(std::string_view ref, const char* what) const {
    std::string_view parts[3];
    int count = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= ref.size(); ++i)
      if (i == ref.size() || ref[i] == '/') {
        if (count == 3) throw fail("corner '" + std::string(ref) + "' of a " + what + " has too many '/'");
        parts[count++] = ref.substr(start, i - start);
        start = i + 1;
      }
    const std::size_t available[3] = {data_.positions.size(), data_.texcoords.size(), data_.normals.size()};
    const char* names[3] = {"vertex", "texture coordinate", "normal"};
    int resolved[3] = {-1, -1, -1};
    for (int k = 0; k < count; ++k) {
      if (parts[k].empty() && k > 0) continue;  // v//vn leaves the uv out
      long long index = 0;
      if (!parseIndex(parts[k], index) || index == 0)
        throw fail("corner '" + std::string(ref) + "' of a " + what + " is not a valid index");
      const long long n = static_cast<long long>(available[k]);
      if (index > n || index < -n)
        throw fail(std::string(what) + " " + names[k] + " index " + std::to_string(index) + " is out of range (" +
                   std::to_string(n) + " defined so far)");
      resolved[k] = int(index > 0 ? index - 1 : n + index);
    }
    return {resolved[0], resolved[1], resolved[2]};
  }

  ObjData data_;
  std::vector<std::string_view> tok_;
  std::size_t line_ = 0;
};

// ---- triangulation ------------------------------------------------------------------------------
// No packaged library fits: tinyobjloader 2.0.0rc10 (Debian 12) ear-clips with a convexity test
// against the triangle (origin, v0, v1), so a concave polygon away from the origin lost triangles
// (a pentagon came out as 1 triangle instead of 3), and mapbox earcut is not packaged for Debian
// 12. Convex polygons are fanned (quads split along the shorter diagonal), a concave quad at its
// reflex corner; any other concave or self-crossing polygon is an error naming its line.

// The polygon's corners projected onto the plane of its Newell normal (2D, counter-clockwise
// when seen against the normal); false when the polygon has no area at all.
bool project(const ObjData& d, const ObjData::Face& f, std::vector<glm::dvec2>& out) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < f.count; ++i) {
    const glm::dvec3 a = d.positions[std::size_t(d.corners[f.first + i].v)];
    const glm::dvec3 b = d.positions[std::size_t(d.corners[f.first + (i + 1) % f.count].v)];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double length = glm::length(n);
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  n /= length;
  const glm::dvec3 u =
      glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(n, u);
  out.clear();
  for (std::size_t i = 0; i < f.count; ++i) {
    const glm::dvec3 p = d.positions[std::size_t(d.corners[f.first + i].v)];
    out.emplace_back(glm::dot(p, u), glm::dot(p, v));
  }
  return true;
}

// Reflex corners (turning clockwise), and whether the boundary winds around once.
struct Turns {
  std::vector<std::size_t> reflex;
  bool windsOnce = true;
};
Turns turns(const std::vector<glm::dvec2>& p) {
  std::vector<std::size_t> distinct;  // corners where the outline moves on (repeats turn nowhere)
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] != p[(i + p.size() - 1) % p.size()]) distinct.push_back(i);
  Turns t;
  double total = 0.0;
  const std::size_t n = distinct.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 a = p[distinct[(k + n - 1) % n]], b = p[distinct[k]], c = p[distinct[(k + 1) % n]];
    const glm::dvec2 in = b - a, out = c - b;
    const double cross = in.x * out.y - in.y * out.x, dot = glm::dot(in, out);
    if (cross < -1e-9 * glm::length(in) * glm::length(out)) t.reflex.push_back(distinct[k]);
    total += std::atan2(cross, dot);
  }
  t.windsOnce = n < 3 || std::abs(total - 2.0 * 3.14159265358979) < 0.5;
  return t;
}

void triangulate(const ObjData& d, const ObjData::Face& f, std::vector<ObjData::Corner>& out) {
  auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
    for (std::size_t k : {a, b, c}) out.push_back(d.corners[f.first + k % f.count]);
  };
  std::vector<glm::dvec2> p;
  const bool flat = f.count > 3 && project(d, f, p);  // false: a triangle, or no area to judge
  const Turns t = flat ? turns(p) : Turns{};
  const auto where = "line " + std::to_string(f.line) + ": a face with " + std::to_string(f.count) + " corners ";
  if (!t.reflex.empty() && f.count == 4 && t.reflex.size() == 1) {  // a dart: split at its reflex corner
    const std::size_t r = t.reflex[0];
    emit(r, r + 1, r + 2);
    emit(r, r + 2, r + 3);
    return;
  }
  if (!t.reflex.empty())
    throw ObjError(where + "is concave (corner " + std::to_string(t.reflex[0] + 1) +
                   " turns inward); this loader splits convex polygons and concave quads only: triangulate it "
                   "when exporting (Blender: Triangulate Faces)");
  if (!t.windsOnce) throw ObjError(where + "crosses itself; triangulate it when exporting");
  if (flat && f.count == 4 && glm::distance(p[0], p[2]) > glm::distance(p[1], p[3])) {
    emit(0, 1, 3);  // the shorter diagonal: better-shaped triangles
    emit(1, 2, 3);
    return;
  }
  for (std::size_t k = 1; k + 1 < f.count; ++k) emit(0, k, k + 1);
}

// ---- the mesh -----------------------------------------------------------------------------------

Mesh buildMesh(const ObjData& d, const std::vector<ObjData::Corner>& corners) {
  // Smooth normals per OBJ position, for corners whose file gives none (or a zero one).
  std::vector<glm::vec3> smooth(d.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < corners.size(); t += 3) {
    const auto a = std::size_t(corners[t].v), b = std::size_t(corners[t + 1].v), c = std::size_t(corners[t + 2].v);
    const glm::vec3 n = glm::cross(d.positions[b] - d.positions[a], d.positions[c] - d.positions[a]);  // area-weighted
    smooth[a] += n;
    smooth[b] += n;
    smooth[c] += n;
  }
  struct KeyHash {
    std::size_t operator()(const ObjData::Corner& k) const {
      return std::size_t(k.v) * 0x9E3779B1u ^ std::size_t(k.vt + 1) * 0x85EBCA77u ^ std::size_t(k.vn + 1) * 0xC2B2AE3Du;
    }
  };
  struct KeyEqual {
    bool operator()(const ObjData::Corner& a, const ObjData::Corner& b) const {
      return a.v == b.v && a.vt == b.vt && a.vn == b.vn;
    }
  };
  std::unordered_map<ObjData::Corner, std::uint32_t, KeyHash, KeyEqual> vertexOf;
  Mesh mesh;
  mesh.indices.reserve(corners.size());
  for (const ObjData::Corner& c : corners) {
    auto [it, inserted] = vertexOf.emplace(c, std::uint32_t(mesh.positions.size()));
    if (inserted) {
      glm::vec3 n = c.vn >= 0 ? d.normals[std::size_t(c.vn)] : glm::vec3(0.0f);
      if (!(glm::length(n) > 1e-20f)) n = smooth[std::size_t(c.v)];
      const float len = glm::length(n);
      const glm::vec2 uv = c.vt >= 0
                               ? glm::vec2(d.texcoords[std::size_t(c.vt)].x, 1.0f - d.texcoords[std::size_t(c.vt)].y)
                               : glm::vec2(0.0f);
      mesh.positions.push_back(d.positions[std::size_t(c.v)]);
      mesh.normals.push_back(len > 1e-20f && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0));
      mesh.uvs.push_back(uv);
    }
    mesh.indices.push_back(it->second);
  }
  return mesh;
}

}  // namespace

Mesh parseObj(const std::string& text) {
  const ObjData data = Parser().run(text);
  if (data.faces.empty()) throw ObjError("no faces");
  std::vector<ObjData::Corner> corners;
  for (const ObjData::Face& f : data.faces) triangulate(data, f, corners);
  return buildMesh(data, corners);
}

Mesh loadObj(const std::string& path) {
  const std::string where = "loadObj('" + path + "'): ";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::runtime_error(where + "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error(where + "not a regular file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(where + "cannot open the file");
  std::ostringstream buffer;
  buffer << file.rdbuf();
  if (file.bad()) throw std::runtime_error(where + "read error");
  try {
    return parseObj(buffer.str());
  } catch (const ObjError& e) { throw std::runtime_error(where + e.what()); }
}

}  // namespace shadowlab

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

#include <tiny_obj_loader.h>

namespace shadowlab {

namespace {

struct ObjError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<std::string_view> tokens(std::string_view line) {
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

bool parseNumber(std::string_view text, double& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // OBJ exporters write "+1.0"
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

bool parseIndex(std::string_view text, long long& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
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

// The light pre-scan: tinyobjloader skips unknown statements, reads garbage numbers as 0 and
// reports out-of-range indices only against the last line, so the line of an error is found
// here, where the counts so far are known. Only the statements a mesh needs (v, vt, vn, f) are
// copied to `kept`, so tinyobjloader never parses the rarer ones (its tag parser trusts counts).
std::size_t validate(const std::string& text, std::string& kept) {
  std::size_t vertices = 0, texcoords = 0, normals = 0, faces = 0;
  std::size_t lineNumber = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    auto fail = [&](const std::string& why) -> ObjError {
      return ObjError("line " + std::to_string(lineNumber) + ": " + why);
    };
    for (char c : line)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
        throw fail("binary data (control character " + std::to_string(int(static_cast<unsigned char>(c))) + ")");
    const std::vector<std::string_view> tok = tokens(line);
    if (tok.empty() || tok[0].front() == '#') continue;
    const std::string_view keyword = tok[0];
    auto numbers = [&](std::size_t minCount, std::size_t maxCount, const char* what) {
      const std::size_t n = tok.size() - 1;
      if (n < minCount || n > maxCount)
        throw fail(std::string(what) + " needs " + std::to_string(minCount) +
                   (maxCount != minCount ? " to " + std::to_string(maxCount) : std::string()) + " numbers, got " +
                   std::to_string(n));
      for (std::size_t i = 1; i < tok.size(); ++i) {
        double value;
        if (!parseNumber(tok[i], value)) throw fail("'" + std::string(tok[i]) + "' is not a finite number in " + what);
      }
    };
    // One corner of a face, line or point: v, v/vt, v//vn or v/vt/vn; negative is relative.
    auto corner = [&](std::string_view ref, const char* what) {
      std::string_view parts[3];
      int count = 0;
      std::size_t start = 0;
      for (std::size_t i = 0; i <= ref.size(); ++i)
        if (i == ref.size() || ref[i] == '/') {
          if (count == 3) throw fail("corner '" + std::string(ref) + "' of a " + what + " has too many '/'");
          parts[count++] = ref.substr(start, i - start);
          start = i + 1;
        }
      const std::size_t available[3] = {vertices, texcoords, normals};
      const char* names[3] = {"vertex", "texture coordinate", "normal"};
      for (int k = 0; k < count; ++k) {
        if (parts[k].empty() && k > 0) continue;  // v//vn leaves the uv out
        long long index = 0;
        if (!parseIndex(parts[k], index) || index == 0)
          throw fail("corner '" + std::string(ref) + "' of a " + what + " is not a valid index");
        const long long n = static_cast<long long>(available[k]);
        if (index > n || index < -n)
          throw fail(std::string(what) + " " + names[k] + " index " + std::to_string(index) + " is out of range (" +
                     std::to_string(n) + " defined so far)");
      }
    };
    bool keep = true;
    if (keyword == "v") numbers(3, 7, "vertex"), ++vertices;
    else if (keyword == "vt") numbers(1, 3, "texture coordinate"), ++texcoords;
    else if (keyword == "vn") numbers(3, 3, "normal"), ++normals;
    else if (keyword == "f") {
      if (tok.size() < 4) throw fail("a face needs at least 3 corners, got " + std::to_string(tok.size() - 1));
      for (std::size_t i = 1; i < tok.size(); ++i) corner(tok[i], "face");
      ++faces;
    } else keep = false;
    if (keep) {
      kept.append(line);
      kept.push_back('\n');
      continue;
    }
    if (keyword == "vp") numbers(1, 3, "parameter vertex");
    else if (keyword == "l" || keyword == "p") {
      for (std::size_t i = 1; i < tok.size(); ++i) corner(tok[i], keyword == "l" ? "line" : "point");
    } else if (!ignoredStatements().count(keyword)) {
      const std::string shown = keyword.size() > 24 ? std::string(keyword.substr(0, 24)) + "..." : std::string(keyword);
      throw fail("unknown statement '" + shown + "'");
    }
  }
  return faces;
}

}  // namespace

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
  const std::string text = buffer.str();

  std::size_t faces = 0;
  std::string kept;
  try {
    faces = validate(text, kept);
  } catch (const ObjError& e) { throw std::runtime_error(where + e.what()); }
  if (faces == 0) throw std::runtime_error(where + "no faces");

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream stream(kept);
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, nullptr, true, false))
    throw std::runtime_error(where + (err.empty() ? "tinyobjloader failed" : err));

  const std::size_t positionCount = attrib.vertices.size() / 3;
  auto position = [&](int i) {
    return glm::vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  };
  // Triangles as corner triplets; tinyobjloader triangulates, a fan covers anything it left.
  std::vector<tinyobj::index_t> corners;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (unsigned char count : shape.mesh.num_face_vertices) {
      if (offset + count > shape.mesh.indices.size()) break;
      for (unsigned k = 1; k + 1 < count; ++k) {
        corners.push_back(shape.mesh.indices[offset]);
        corners.push_back(shape.mesh.indices[offset + k]);
        corners.push_back(shape.mesh.indices[offset + k + 1]);
      }
      offset += count;
    }
  }
  for (const tinyobj::index_t& c : corners)
    if (c.vertex_index < 0 || std::size_t(c.vertex_index) >= positionCount)
      throw std::runtime_error(where + "face refers to a missing vertex");  // the pre-scan should stop this

  // Smooth normals per OBJ position, for corners whose file gives none (or a zero one).
  std::vector<glm::vec3> smooth(positionCount, glm::vec3(0.0f));
  for (std::size_t t = 0; t < corners.size(); t += 3) {
    const int a = corners[t].vertex_index, b = corners[t + 1].vertex_index, c = corners[t + 2].vertex_index;
    const glm::vec3 n = glm::cross(position(b) - position(a), position(c) - position(a));  // area-weighted
    smooth[a] += n;
    smooth[b] += n;
    smooth[c] += n;
  }

  Mesh mesh;
  struct Key {
    int v, vt, vn;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.v) * 0x9E3779B1u ^ std::size_t(k.vt + 1) * 0x85EBCA77u ^ std::size_t(k.vn + 1) * 0xC2B2AE3Du;
    }
  };
  std::unordered_map<Key, std::uint32_t, KeyHash> vertexOf;
  mesh.indices.reserve(corners.size());
  for (const tinyobj::index_t& c : corners) {
    const Key key{c.vertex_index, c.texcoord_index, c.normal_index};
    auto [it, inserted] = vertexOf.emplace(key, std::uint32_t(mesh.positions.size()));
    if (inserted) {
      glm::vec3 n(0.0f);
      if (c.normal_index >= 0 && std::size_t(c.normal_index) * 3 + 2 < attrib.normals.size())
        n = {attrib.normals[3 * c.normal_index], attrib.normals[3 * c.normal_index + 1],
             attrib.normals[3 * c.normal_index + 2]};
      if (!(glm::length(n) > 1e-20f)) n = smooth[c.vertex_index];
      const float len = glm::length(n);
      glm::vec2 uv(0.0f);
      if (c.texcoord_index >= 0 && std::size_t(c.texcoord_index) * 2 + 1 < attrib.texcoords.size())
        uv = {attrib.texcoords[2 * c.texcoord_index], 1.0f - attrib.texcoords[2 * c.texcoord_index + 1]};
      mesh.positions.push_back(position(c.vertex_index));
      mesh.normals.push_back(len > 1e-20f && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0));
      mesh.uvs.push_back(uv);
    }
    mesh.indices.push_back(it->second);
  }
  return mesh;
}

}  // namespace shadowlab

// OBJ loading: fixtures in tests/data/obj with hand-derived expectations, errors that name the
// file and the line, and garbage that must end in an exception, never a crash.
#include <doctest/doctest.h>

#include <initializer_list>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/mesh.hpp"
#include "core/mesh_gen.hpp"
#include "core/obj_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

const std::string kDir = SHADOWLAB_TEST_DATA "/obj/";

// The message of the runtime_error `path` raises, or "" when it loads.
std::string loadError(const std::string& path) {
  try {
    loadObj(path);
  } catch (const std::runtime_error& e) { return e.what(); }
  return {};
}

struct TempFile {
  std::string path;
  explicit TempFile(const std::string& name, const std::string& contents)
      : path((std::filesystem::temp_directory_path() / ("shadowlab_" + name)).string()) {
    std::ofstream(path, std::ios::binary) << contents;
  }
  ~TempFile() { std::filesystem::remove(path); }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("obj: a quad cube with normals and uvs") {
  const Mesh m = loadObj(kDir + "good.obj");
  // 6 quads -> 12 triangles; each face has its own normal, so 6 x 4 distinct corners.
  CHECK(m.triangleCount() == 12);
  CHECK(m.vertexCount() == 24);
  CHECK(m.bounds().min == glm::vec3(-0.5f));
  CHECK(m.bounds().max == glm::vec3(0.5f));
  CHECK(analyseTopology(m).closed());
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
    // The file's normals are the faces' own; the windings agree with them.
    CHECK(glm::dot(face, m.normals[m.indices[t]]) == doctest::Approx(1.0f));
  }
  // OBJ's v = 0 is the image's bottom row: it arrives as 1.
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    CHECK((m.uvs[i].x == 0.0f || m.uvs[i].x == 1.0f));
    flipped += m.uvs[i] == glm::vec2(0.0f, 1.0f);
  }
  CHECK(flipped == 6);  // vt 1 = (0,0) is one corner of every face
}

TEST_CASE("obj: missing normals are computed, missing uvs are zero") {
  const Mesh m = loadObj(kDir + "missing_normals.obj");
  CHECK(m.triangleCount() == 4);
  CHECK(m.vertexCount() == 4);
  CHECK(analyseTopology(m).closed());
  // Area-weighted sums of the adjacent face normals (worked out by hand for this tetrahedron):
  // the corner on each axis gets that axis, the origin gets -(1,1,1)/sqrt(3).
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 p = m.positions[i];
    const glm::vec3 expected = p == glm::vec3(0.0f) ? -glm::normalize(glm::vec3(1.0f)) : p;
    CHECK(glm::dot(m.normals[i], expected) == doctest::Approx(1.0f));
    CHECK(m.uvs[i] == glm::vec2(0.0f));
  }
}

TEST_CASE("obj: syntax errors name the file and the line") {
  const std::string malformed = loadError(kDir + "malformed.obj");
  CHECK(contains(malformed, "malformed.obj"));
  CHECK(contains(malformed, "line 5"));
  CHECK(contains(malformed, "abc"));
  const std::string range = loadError(kDir + "out_of_range.obj");
  CHECK(contains(range, "out_of_range.obj"));
  CHECK(contains(range, "line 8"));
  CHECK(contains(range, "out of range"));
}

TEST_CASE("obj: missing files, directories and empty files are errors that name the path") {
  const std::string missing = loadError(kDir + "no_such_file.obj");
  CHECK(contains(missing, "no_such_file.obj"));
  CHECK(contains(loadError(kDir), kDir));
  TempFile empty("empty.obj", "# nothing\nv 0 0 0\n");
  CHECK(contains(loadError(empty.path), "no faces"));
}

TEST_CASE("obj: polygons, relative indices and statements that carry nothing") {
  TempFile file("poly.obj",
                "mtllib nowhere.mtl\r\no pentagon\nv 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                "usemtl red\ns 1\nf -5 -4 -3 -2 -1\nl 1 2\n");
  const Mesh m = loadObj(file.path);
  CHECK(m.triangleCount() == 3);  // a convex pentagon: n - 2 triangles
  CHECK(m.vertexCount() == 5);
  for (const glm::vec3& n : m.normals) CHECK(n.z == doctest::Approx(1.0f));
  const char* bad[][2] = {{"f 1 2\n", "line 4"},           // two corners
                          {"f 1 2 0\n", "line 4"},         // index 0 does not exist
                          {"f 1 2 -4\n", "line 4"},        // relative past the start
                          {"f 1/1 2 3\n", "line 4"},       // no uvs defined
                          {"f 1 2 3x\n", "line 4"},        // not a number
                          {"vn 1 0\n", "line 4"},          // too few numbers
                          {"v 1 nan 2\n", "line 4"},       // not finite
                          {"bogus 1 2 3\n", "line 4"},     // unknown statement
                          {"f 1/2/3/4 2 3\n", "line 4"}};  // too many slashes
  for (const auto& [line, where] : bad) {
    INFO(line);
    TempFile broken("broken.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + line);
    const std::string message = loadError(broken.path);
    CHECK(contains(message, "broken.obj"));
    CHECK(contains(message, where));
  }
}

TEST_CASE("obj: garbage never crashes, it loads or throws runtime_error") {
  SplitMix64 rng(test::seedFor("obj garbage"));
  const std::string alphabet = "vtnf/ -0123456789.e#\n\n\tgos";
  std::size_t loaded = 0, rejected = 0;
  for (int round = 0; round < 300; ++round) {
    std::string text;
    const int length = 1 + rng.below(200);
    for (int i = 0; i < length; ++i)
      text.push_back(round % 3 == 0 ? char(rng.below(256)) : alphabet[rng.below(int(alphabet.size()))]);
    if (round % 5 == 0) text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + text;
    TempFile file("garbage.obj", text);
    try {
      const Mesh m = loadObj(file.path);
      ++loaded;
      CHECK(m.normals.size() == m.positions.size());
      for (std::uint32_t i : m.indices) CHECK(i < m.vertexCount());
    } catch (const std::runtime_error& e) {
      ++rejected;
      CHECK(contains(e.what(), "garbage.obj"));
    }
  }
  CHECK(rejected > 0);
}

TEST_CASE("obj: the fuzzing finds: numbers are what they say or an error naming the line") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  auto errorOf = [](const std::string& text) {
    try {
      parseObj(text);
    } catch (const std::runtime_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  // 0e999999 is zero (tinyobjloader read NaN); 1e39 is past a float (it read inf).
  const Mesh zero = parseObj("v 0e999999 0 0\nv 1 0 0\nv 0 1 0\nvt 0e999 0\nf 1/1 2/1 3/1\n");
  CHECK(zero.positions[0] == glm::vec3(0.0f));
  CHECK(zero.uvs[0] == glm::vec2(0.0f, 1.0f));
  CHECK(errorOf("v 1e39 0 0\n" + tri) == "line 1: '1e39' is outside a float's range in vertex");
  CHECK(errorOf("v 0 -1e39 0\n" + tri) == "line 1: '-1e39' is outside a float's range in vertex");
  CHECK(errorOf(tri + "vt 1e-50 0\n") == "line 4: '1e-50' is outside a float's range in texture coordinate");
  // "+-5" was read as 0.
  for (const char* bad : {"+-5", "-+5", "++5", "--5", "0x10", "inf", "-nan", "1e", ".", "5,0"}) {
    INFO(bad);
    CHECK(errorOf(tri + "v " + bad + " 0 0\n") ==
          "line 4: '" + std::string(bad) + "' is not a finite number in vertex");
  }
  CHECK(parseObj("v +1.5 -2 .5\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").positions[0] == glm::vec3(1.5f, -2.0f, 0.5f));
  // A comment after a statement is valid OBJ (it was refused), with or without a space before it.
  const Mesh commented = parseObj("v 0 0 0 # origin\nv 1 0 0\t# x\nv 0 1 0#y\nusemtl red#2\nf 1 2 3 # face\n");
  CHECK(commented.triangleCount() == 1);
  CHECK(errorOf(tri + "f 1 2# 3\n") == "line 4: a face needs at least 3 corners, got 2");
}

TEST_CASE("obj: polygons: convex ones fan, a concave quad splits at its reflex corner, others are refused by line") {
  // tinyobjloader 2.0.0rc10 clipped ears against the triangle (origin, v0, v1): away from the
  // origin this concave pentagon came out as 1 triangle.
  const std::string pentagon = "v 10 10 0\nv 12 10 0\nv 12 12 0\nv 11 11 0\nv 10 12 0\n";
  try {
    parseObj(pentagon + "f 1 2 3 4 5\n");
    FAIL("a concave pentagon loaded");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) ==
          "line 6: a face with 5 corners is concave (corner 4 turns inward); this loader splits convex polygons and "
          "concave quads only: triangulate it when exporting (Blender: Triangulate Faces)");
  }
  // The same outline as a dart quad and as triangles: both load, covering the area exactly.
  auto area = [](const Mesh& m) {
    double sum = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      sum += 0.5 * glm::length(glm::cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                          m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]));
    return sum;
  };
  for (const char* face : {"f 1 2 3 4\n", "f 2 3 4 1\n", "f 3 4 1 2\n", "f 4 1 2 3\n", "f 4 3 2 1\n"}) {
    INFO(face);
    const Mesh dart = parseObj("v 10 10 5\nv 14 12 5\nv 10 14 5\nv 11 12 5\n" + std::string(face));
    CHECK(dart.triangleCount() == 2);
    CHECK(area(dart) == doctest::Approx(6.0));  // 8 (the hull) - 2 (the notch)
  }
  // Convex polygons anywhere, in any plane: n - 2 triangles covering the polygon.
  const Mesh hexagon =
      parseObj("v 101 0 50\nv 102 0 50\nv 103 0 51\nv 102 0 52\nv 101 0 52\nv 100 0 51\nf 1 2 3 4 5 6\n");
  CHECK(hexagon.triangleCount() == 4);
  CHECK(area(hexagon) == doctest::Approx(4.0));
  // A pentagram winds twice: refused, never fanned into overlapping triangles.
  std::string star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * 3.14159265358979 * (2 * i) / 5;
    star += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  try {
    parseObj(star + "f 1 2 3 4 5\n");
    FAIL("a pentagram loaded");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "line 6: a face with 5 corners crosses itself; triangulate it when exporting");
  }
  // Collinear and repeated corners turn nowhere: still convex.
  CHECK(parseObj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4 5 5\n").triangleCount() == 4);
}

TEST_CASE("obj: a quad with no area (repeated corners) fans without reading past its projection (libFuzzer find)") {
  const Mesh m = loadObj(SHADOWLAB_SOURCE_ROOT "/tests/fuzz/obj/regressions/quad_without_area.obj");
  CHECK(m.triangleCount() == 4);
  for (const glm::vec3& n : m.normals) CHECK(glm::length(n) == doctest::Approx(1.0f));
}

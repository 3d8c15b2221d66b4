// Model files through Assimp (core/model_file): the committed models in tests/data/models (a
// textured OBJ + MTL, glTF 2.0 as .gltf and .glb, and broken ones), the OBJ fixtures the
// hand-written parser was tested on (tests/data/obj), the libFuzzer regressions, and garbage that
// must end in a ModelError naming the file, never a crash.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/mesh_gen.hpp"
#include "core/model_file.hpp"
#include "core/obj_locate.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

const std::string kModels = test::testData() + "/models/";
const std::string kObj = test::testData() + "/obj/";

// The message of the ModelError loading `path` raises, or "" when it loads.
std::string loadError(const std::string& path) {
  try {
    loadModelFile(path);
  } catch (const ModelError& e) { return e.what(); }
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool anyNote(const ModelFile& m, const std::string& part) {
  for (const std::string& note : m.notes)
    if (contains(note, part)) return true;
  return false;
}

// All the file's triangles in one mesh, in world space (node transforms applied).
Mesh flatten(const Scene& scene) {
  Mesh all;
  for (const SceneObject& o : scene.objects) all.append(scene.meshes[o.mesh], o.model);
  return all;
}

double area(const Mesh& m) {
  double sum = 0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    sum += 0.5 * glm::length(glm::cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                        m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]));
  return sum;
}

// What every loaded model promises (the fuzz target checks the same).
void checkInvariants(const ModelFile& model) {
  REQUIRE_FALSE(model.scene.objects.empty());
  for (const SceneObject& o : model.scene.objects) {
    REQUIRE(o.mesh < model.scene.meshes.size());
    REQUIRE(o.material < model.scene.materials.size());
  }
  for (const Mesh& m : model.scene.meshes) {
    CHECK(m.indices.size() % 3 == 0);
    CHECK(m.normals.size() == m.positions.size());
    CHECK(m.uvs.size() == m.positions.size());
    for (std::uint32_t i : m.indices) CHECK(i < m.vertexCount());
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
      CHECK(std::isfinite(m.positions[i].x + m.positions[i].y + m.positions[i].z));
      CHECK(glm::length(m.normals[i]) == doctest::Approx(1.0f).epsilon(1e-3));
      CHECK(std::isfinite(m.uvs[i].x + m.uvs[i].y));
    }
  }
}

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("model: an OBJ cube with its MTL: the diffuse colour, and the texture found beside the model") {
  const ModelFile m = loadModelFile(kModels + "cube.obj");
  checkInvariants(m);
  CHECK(m.notes.empty());
  const Mesh all = flatten(m.scene);
  CHECK(all.triangleCount() == 12);
  CHECK(analyseTopology(all).closed());
  CHECK(m.scene.bounds().min == glm::vec3(-0.5f));
  CHECK(m.scene.bounds().max == glm::vec3(0.5f));
  const Material& crate = m.scene.materials.at(m.scene.objects.at(0).material);
  CHECK(crate.name == "crate");
  CHECK(crate.albedo == glm::vec3(0.9f, 0.5f, 0.2f));
  CHECK(crate.shininess == 32.0f);
  CHECK(std::filesystem::path(crate.texture).is_absolute());
  CHECK(std::filesystem::equivalent(crate.texture, kModels + "crate.png"));
}

TEST_CASE("model: glTF 2.0, as .gltf with a data URI and as .glb, gives the same tetrahedron and material") {
  for (const char* file : {"tetrahedron.gltf", "tetrahedron.glb"}) {
    INFO(file);
    const ModelFile m = loadModelFile(kModels + file);
    checkInvariants(m);
    CHECK(m.notes.empty());
    const Mesh all = flatten(m.scene);
    CHECK(all.triangleCount() == 4);
    CHECK(analyseTopology(all).closed());
    CHECK(m.scene.bounds().min == glm::vec3(0, 0, -1));
    CHECK(m.scene.bounds().max == glm::vec3(1, 1, 0));
    const Material& blue = m.scene.materials.at(m.scene.objects.at(0).material);
    CHECK(blue.name == "blue");
    CHECK(blue.albedo.x == doctest::Approx(0.2f));
    CHECK(blue.albedo.y == doctest::Approx(0.3f));
    CHECK(blue.albedo.z == doctest::Approx(0.9f));
    CHECK(blue.texture.empty());
  }
}

TEST_CASE("model: quads and a concave pentagon are triangulated, covering their area exactly") {
  const ModelFile m = loadModelFile(kModels + "quads.obj");
  checkInvariants(m);
  const Mesh all = flatten(m.scene);
  CHECK(all.triangleCount() == 6 * 2 + 3);  // six quads, and a pentagon's n - 2
  INFO("area " << area(all));
  CHECK(area(all) == doctest::Approx(6.0 + 3.0));  // the cube's faces; the arrow is 4 - 1
}

TEST_CASE("model: missing normals are generated, and said so") {
  const ModelFile m = loadModelFile(kModels + "no_normals.obj");
  checkInvariants(m);
  CHECK(m.meshesWithoutNormals == 1);
  CHECK(anyNote(m, "no normals: generated"));
  // A cube's edges are 90-degree creases, over the 60 degrees smoothed: each corner keeps its face's normal.
  const Mesh all = flatten(m.scene);
  for (std::size_t t = 0; t < all.indices.size(); t += 3) {
    const glm::vec3 a = all.positions[all.indices[t]], b = all.positions[all.indices[t + 1]],
                    c = all.positions[all.indices[t + 2]];
    const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
    for (std::size_t k = 0; k < 3; ++k) CHECK(glm::dot(all.normals[all.indices[t + k]], face) == doctest::Approx(1.0f));
  }
  // A roof bent by 20 degrees is smoothed: the ridge's normals are the mean of the two faces' (+y).
  const std::string roof =
      "v -1 0 -1\nv -1 0 1\nv 0 0.176327 -1\nv 0 0.176327 1\nv 1 0 -1\nv 1 0 1\n"
      "f 1 2 4\nf 1 4 3\nf 3 4 5\nf 4 6 5\n";  // per ridge corner, as many triangles each side
  const ModelFile bent = loadModelFromMemory(roof.data(), roof.size(), "obj", "roof.obj");
  checkInvariants(bent);
  CHECK(bent.meshesWithoutNormals == 1);
  const Mesh r = flatten(bent.scene);
  std::size_t ridge = 0;
  for (std::size_t i = 0; i < r.vertexCount(); ++i)
    if (r.positions[i].x == 0.0f) {
      ++ridge;
      CHECK(glm::dot(r.normals[i], glm::vec3(0, 1, 0)) == doctest::Approx(1.0f));
    }
  CHECK(ridge == 2);
  CHECK(loadModelFile(kModels + "cube.obj").meshesWithoutNormals == 0);
}

TEST_CASE("model: a missing texture names the file and the diffuse colour used instead") {
  const ModelFile m = loadModelFile(kModels + "missing_texture.obj");
  checkInvariants(m);
  CHECK(m.missingTextures == 1);
  REQUIRE(m.notes.size() == 1);
  CHECK(contains(m.notes[0], "no_such_texture.png' not found"));
  CHECK(contains(m.notes[0], "material 'painted' uses its diffuse colour (0.20, 0.70, 0.30)"));
  const Material& painted = m.scene.materials.at(m.scene.objects.at(0).material);
  CHECK(painted.texture.empty());
  CHECK(painted.albedo == glm::vec3(0.2f, 0.7f, 0.3f));
}

TEST_CASE("model: points and lines are skipped and counted, a file of nothing else is an error") {
  const ModelFile m = loadModelFile(kModels + "mixed_primitives.obj");
  checkInvariants(m);
  CHECK(flatten(m.scene).triangleCount() == 1);
  CHECK(m.skippedPoints == 2);
  CHECK(m.skippedLines == 1);
  CHECK(anyNote(m, "skipped 2 points and 1 lines"));
  const std::string lines = loadError(kModels + "lines_only.obj");
  CHECK(contains(lines, "lines_only.obj"));
  CHECK(contains(lines, "no triangles to draw"));
}

TEST_CASE("model: missing, empty, truncated, corrupt and oversized files are one-line errors naming the file") {
  const std::string cases[][2] = {{kModels + "no_such_model.obj", "no such file"},
                                  {kModels, "not a regular file"},
                                  {kModels + "empty.obj", "the file is empty"},
                                  {kModels + "truncated.glb", "not a readable model file"},
                                  {kModels + "corrupt.gltf", "not a readable model file"},
                                  {kObj + "out_of_range.obj",
                                   "line 8: vertex index 9 is past the file's 3 vertices (valid: 1 to 3, "
                                   "or -1 to -3 counting back from the last vertex so far)"},
                                  // Assimp drops the garbled vertex; the face then indexes past the rest.
                                  {kObj + "malformed.obj",
                                   "line 5: 'abc' is not a number (valid: numbers such as 2, -0.5 or 1.5e-3, "
                                   "a digit first)"}};
  for (const auto& [path, reason] : cases) {
    const std::string& shown = path;  // INFO captures in a lambda: not a structured binding (clang 14)
    INFO(shown);
    const std::string message = loadError(path);
    CHECK(message.rfind("model '" + path + "': ", 0) == 0);
    CHECK(contains(message, reason));
    CHECK_FALSE(contains(message, "\n"));
  }
  // A sparse file just over the limit: refused by its size, before Assimp reads a byte.
  const std::string huge = (std::filesystem::temp_directory_path() / "shadowlab_huge_model.obj").string();
  std::ofstream(huge).put('v');
  std::filesystem::resize_file(huge, kMaxModelBytes + 1);
  CHECK(contains(loadError(huge), "MiB is over the 512 MiB limit"));
  std::filesystem::remove(huge);
}

TEST_CASE("model: the OBJ fixtures of the former hand-written parser load the same through Assimp") {
  const ModelFile good = loadModelFile(kObj + "good.obj");
  checkInvariants(good);
  const Mesh m = flatten(good.scene);
  CHECK(m.triangleCount() == 12);
  CHECK(m.vertexCount() == 24);  // each face has its own normal: 6 x 4 distinct corners
  CHECK(analyseTopology(m).closed());
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    CHECK(glm::dot(glm::normalize(glm::cross(b - a, c - a)), m.normals[m.indices[t]]) == doctest::Approx(1.0f));
  }
  // OBJ's v = 0 is the image's bottom row: it arrives as 1.
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < m.vertexCount(); ++i) flipped += m.uvs[i] == glm::vec2(0.0f, 1.0f);
  CHECK(flipped == 6);  // vt 1 = (0,0) is one corner of every face

  const ModelFile tetra = loadModelFile(kObj + "missing_normals.obj");
  checkInvariants(tetra);
  CHECK(tetra.meshesWithoutNormals == 1);
  const Mesh t = flatten(tetra.scene);
  CHECK(t.triangleCount() == 4);
  CHECK(analyseTopology(t).closed());
  for (std::size_t i = 0; i < t.vertexCount(); ++i) {
    CHECK(t.uvs[i] == glm::vec2(0.0f));
    // Outward: away from the tetrahedron's centroid.
    CHECK(glm::dot(t.normals[i], t.positions[i] - glm::vec3(0.25f)) > 0.0f);
  }
  // Its faces meet at 90 and 125 degrees, creases all: every corner has its face's normal.
  for (std::size_t k = 0; k < t.indices.size(); k += 3) {
    const glm::vec3 a = t.positions[t.indices[k]], b = t.positions[t.indices[k + 1]], c = t.positions[t.indices[k + 2]];
    CHECK(glm::dot(t.normals[t.indices[k]], glm::normalize(glm::cross(b - a, c - a))) == doctest::Approx(1.0f));
  }
}

TEST_CASE("model: the libFuzzer regressions of the OBJ parser load with finite numbers or are refused") {
  const std::string dir = test::sourceTree() + "/tests/fuzz/obj/regressions/";
  const char* refused[] = {"exponent_nan.obj", "float_overflow_inf.obj", "sign_sign.obj", "leak_mesh_on_throw.obj"};
  const char* loaded[] = {"concave_pentagon.obj", "quad_without_area.obj", "trailing_comment.obj", "uv_nan.obj"};
  for (const char* file : refused) {
    INFO(file);
    CHECK(contains(loadError(dir + file), file));
  }
  for (const char* file : loaded) {
    INFO(file);
    checkInvariants(loadModelFile(dir + file));
  }
  // Each names its line: Assimp 5.2.5 reads 0e999999 as NaN, and 1e39 overflows a float.
  CHECK(loadError(dir + "exponent_nan.obj") ==
        "model '" + dir +
            "exponent_nan.obj': line 1: '0e999999' is beyond a float's range (valid: magnitudes up "
            "to 3.4e38, exponents up to 38)");
  CHECK(contains(loadError(dir + "float_overflow_inf.obj"), "float_overflow_inf.obj': line 1: '1e39' is beyond"));
  CHECK(contains(loadError(dir + "sign_sign.obj"), "sign_sign.obj': line 1: '+-5' is not a number (valid: "));
  // The input on which the obj fuzz target found Assimp leaking (tests/lsan.supp): refused by line.
  CHECK(contains(loadError(dir + "leak_mesh_on_throw.obj"),
                 "leak_mesh_on_throw.obj': line 3: a face with 1 corner (valid: f with 3 or more corners, l for "
                 "lines, p for points)"));
  const Mesh pentagon = flatten(loadModelFile(dir + "concave_pentagon.obj").scene);
  CHECK(pentagon.triangleCount() == 3);
  CHECK(area(pentagon) == doctest::Approx(3.0));  // Assimp's own triangulation covered the notch: 4
}

TEST_CASE("model: a face that crosses itself is an error naming the file") {
  std::string star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * 3.14159265358979 * (2 * i) / 5;
    star += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  star += "f 1 2 3 4 5\n";
  try {
    loadModelFromMemory(star.data(), star.size(), "obj", "star.obj");
    FAIL("a pentagram loaded");
  } catch (const ModelError& e) {
    CHECK(std::string(e.what()) ==
          "model 'star.obj': line 6: a face with 5 corners crosses itself; triangulate it when exporting (valid: "
          "simple polygons, whose edges meet only at their corners)");
  }
}

namespace {

// The message loading `text` as "bad.obj" from memory raises, or "" when it loads.
std::string objError(const std::string& text) {
  try {
    loadModelFromMemory(text.data(), text.size(), "obj", "bad.obj");
  } catch (const ModelError& e) { return e.what(); }
  return {};
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1 to 3

}  // namespace

TEST_CASE("model: a refused OBJ names the file, the line, the reason and the valid choices, in one line") {
  const std::string number = "(valid: numbers such as 2, -0.5 or 1.5e-3, a digit first)";
  const std::string range = "(valid: magnitudes up to 3.4e38, exponents up to 38)";
  const std::string indices = "(valid: 1 to 3, or -1 to -3 counting back from the last vertex so far)";
  const std::string face = "(valid: f with 3 or more corners, l for lines, p for points)";
  const std::string cases[][2] = {
      // Coordinates Assimp drops (its faces then index past the vertices) or refuses.
      {"v 0 0 0\nv 1 0 0\nv 1.0 abc 0.0\nf 1 2 3\n", "line 3: 'abc' is not a number " + number},
      {"v 0 0 .5\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: '.5' is not a number " + number},
      {kTriangle + "vn 0 abc 1\nf 1//1 2//1 3//1\n", "line 4: 'abc' is not a number " + number},
      {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "line 2: v with 2 numbers (valid: v x y z, v x y z w, or v x y z r g b)"},
      {kTriangle + "vt 0.5\nf 1/1 2/1 3/1\n", "line 4: vt with 1 number (valid: vt u v, or vt u v w)"},
      {kTriangle + "vn 1 0\nf 1//1 2//1 3//1\n", "line 4: vn with 2 numbers (valid: vn x y z)"},
      {"v 0 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: w is 0 (valid: a w other than 0: it divides x, y and z)"},
      // Numbers Assimp reads as NaN or infinity, refused by the loader and found again here.
      {"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
       "line 1: 'nan' is not a finite number (valid: finite numbers such as 2 or -0.5)"},
      {"v 0.00001e40 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: '0.00001e40' is beyond a float's range " + range},
      {kTriangle + "vn 1e39 0 1\nf 1//1 2//1 3//1\n", "line 4: '1e39' is beyond a float's range " + range},
      {"v 1e30 0 0 1e-30\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
       "line 1: dividing 1e30 by w = 1e-30 goes beyond a float's range (valid: coordinates divided by w of "
       "magnitudes up to 3.4e38)"},
      // Faces.
      {kTriangle + "f 1 2 3\nf 1 2\n", "line 5: a face with 2 corners " + face},
      {kTriangle + "f 1\n", "line 4: a face with 1 corner " + face},
      {kTriangle + "l 1\nf 1 2 3\n", "line 4: a line with 1 corner (valid: l with 2 or more corners)"},
      {kTriangle + "f 1 2 x\n",
       "line 4: 'x' is not a vertex index (valid: whole numbers, 1 to 3, or -1 to -3 "
       "counting back from the last vertex so far)"},
      {kTriangle + "f 1 2 3.5\n",
       "line 4: '3.5' is not a vertex index (valid: whole numbers, 1 to 3, or -1 to -3 "
       "counting back from the last vertex so far)"},
      {kTriangle + "f 0 1 2\n", "line 4: vertex index 0: OBJ counts from 1 " + indices},
      {kTriangle + "\n# a comment\nf 1 2 9\n", "line 6: vertex index 9 is past the file's 3 vertices " + indices},
      {kTriangle + "f 1 2 -9\n", "line 4: vertex index -9 reaches before the first vertex " + indices},
      {"f 1 2 3\n",
       "line 1: vertex index 1 is past the file's 0 vertices (valid: v statements first: the file has "
       "none)"},
      {kTriangle + "vt 0 0\nf 1/x 2/1 3/1\n",
       "line 5: 'x' is not a uv index (valid: whole numbers other than 0, or nothing, in '1/x')"},
      {kTriangle + "vn 0 0 1\nf 1//x 2//1 3//1\n",
       "line 5: 'x' is not a normal index (valid: whole numbers other than 0, or nothing, in '1//x')"},
      {kTriangle + "f 1/1/1/1 2 3\n", "line 4: '1/1/1/1' is not a face corner (valid: v, v/vt, v//vn or v/vt/vn)"},
      {kTriangle + "f 1 2 3 # a comment\n",
       "line 4: a comment after a face's corners (valid: the comment on a line of its own: Assimp 5.2.5 refuses "
       "'#' on a face line)"},
      // Statements Assimp misreads or skips.
      {kTriangle + "foo bar\nf 1 2 3\n",
       "line 4: unknown statement 'foo' (valid: v, vt, vn, f, l, p, o, g, s, usemtl, mtllib, #: Assimp reads a word "
       "starting with f as a face)"},
      {kTriangle + "\tf 1 2 3\n",
       "line 4: 'f' is indented (valid: statements that start the line: Assimp 5.2.5 skips lines that begin with a "
       "space or tab)"},
      {"v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n",
       "line 4: vertex index 4 is past the file's 3 vertices " + indices},
  };
  for (const auto& [text, reason] : cases) {
    const std::string& shown = text;  // INFO captures in a lambda: not a structured binding (clang 14)
    INFO(shown);
    const std::string message = objError(text);
    CHECK(message == "model 'bad.obj': " + reason);
    CHECK_FALSE(contains(message, "\n"));
  }
  // Read from a file, the message names its path.
  const std::string path = kObj + "out_of_range.obj";
  CHECK(loadError(path) == "model '" + path + "': line 8: vertex index 9 is past the file's 3 vertices " + indices);
  // Only OBJ files are scanned: a broken glTF keeps the loader's own message, with no line.
  const std::string gltf = loadError(kModels + "corrupt.gltf");
  CHECK(contains(gltf, "not a readable model file"));
  CHECK_FALSE(contains(gltf, ": line "));
}

TEST_CASE("model: a statement Assimp skips or misreads in an OBJ it loads is a note naming the line") {
  // The third vertex garbled: Assimp 5.2.5 drops it and the face takes the fourth instead.
  const std::string garbled = "v 0 0 0\nv 1 0 0\nv 1.0 abc 0.0\nv 0 1 0\nf 1 2 3\n";
  const ModelFile m = loadModelFromMemory(garbled.data(), garbled.size(), "obj", "garbled.obj");
  checkInvariants(m);
  CHECK(anyNote(m,
                "line 3: 'abc' is not a number (valid: numbers such as 2, -0.5 or 1.5e-3, a digit first). "
                "Assimp 5.2.5 loaded the file, skipping or misreading this statement: check the model"));
  // An indented vertex that no face uses: skipped, and said so.
  const std::string indented = kTriangle + "  v 5 5 5\nf 1 2 3\n";
  const ModelFile i = loadModelFromMemory(indented.data(), indented.size(), "obj", "indented.obj");
  CHECK(anyNote(i, "line 4: 'v' is indented"));
  // Well-formed files get no such note: the committed models and fixtures.
  for (const std::string& path : {kModels + "cube.obj", kModels + "quads.obj", kModels + "tent.obj",
                                  kModels + "chimney.obj", kObj + "good.obj", kObj + "missing_normals.obj"}) {
    INFO(path);
    CHECK_FALSE(anyNote(loadModelFile(path), "line "));
  }
}

TEST_CASE("model: the OBJ locator finds the line that explains each refusal, and none in a good file") {
  const std::string text = "v 0 0 0\n v 1 1 1\nv 1 0 0\nvt 0 0\nv 1e39 0 0\nvn 0 0 1\nf 1 2 3\nf 1 2 99\n";
  const auto line = [&](ObjFault fault) {
    const std::optional<ObjLine> at = locateObjFault(text, fault);
    return at ? at->line : 0;
  };
  CHECK(line(ObjFault::any) == 2);                // the first fault of any kind: the indented vertex
  CHECK(line(ObjFault::nonFinitePosition) == 5);  // a NaN or infinite position: the 1e39
  CHECK(line(ObjFault::vertexIndex) == 8);        // a face past the vertices
  CHECK(line(ObjFault::nonFiniteUv) == 0);        // nothing explains these
  CHECK(line(ObjFault::nonFiniteNormal) == 0);
  CHECK(line(ObjFault::selfCrossing) == 0);
  const std::string good = fileText(kObj + "good.obj");
  for (ObjFault fault : {ObjFault::any, ObjFault::nonFinitePosition, ObjFault::nonFiniteUv, ObjFault::nonFiniteNormal,
                         ObjFault::vertexIndex, ObjFault::selfCrossing}) {
    CHECK_FALSE(locateObjFault(good, fault).has_value());
    CHECK_FALSE(locateObjFault("", fault).has_value());
  }
}

TEST_CASE("model: garbage from memory never crashes: it loads with the invariants or throws ModelError") {
  SplitMix64 rng(test::seedFor("model garbage"));
  const std::string alphabet = "vtnfpl/ -0123456789.e#\n\n\tgos";
  std::size_t rejected = 0;
  for (int round = 0; round < 300; ++round) {
    std::string text;
    const int length = 1 + rng.below(200);
    for (int i = 0; i < length; ++i)
      text.push_back(round % 3 == 0 ? char(rng.below(256)) : alphabet[rng.below(int(alphabet.size()))]);
    if (round % 5 == 0) text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + text;
    try {
      checkInvariants(loadModelFromMemory(text.data(), text.size(), "obj", "garbage.obj"));
    } catch (const ModelError& e) {
      ++rejected;
      CHECK(contains(e.what(), "model 'garbage.obj': "));
    }
  }
  CHECK(rejected > 0);
  // The glTF readers on the committed files cut short at every 64th byte.
  const std::string glb = fileText(kModels + "tetrahedron.glb");
  for (std::size_t cut = 1; cut < glb.size(); cut += 64) {
    try {
      checkInvariants(loadModelFromMemory(glb.data(), cut, "glb", "cut.glb"));
    } catch (const ModelError& e) { CHECK(contains(e.what(), "model 'cut.glb': ")); }
  }
}

TEST_CASE("model: placed on the ground: the largest side the given size, centred, standing on y = 0") {
  const ModelFile cube = loadModelFile(kModels + "cube.obj");
  const Scene scene = placeOnGround(cube, 6.0f, 30.0f);
  REQUIRE(scene.objects.size() == 2);
  CHECK(scene.objects[0].name == "ground");
  CHECK_FALSE(scene.objects[0].castsShadow);
  CHECK(scene.objectBounds(0).extent().x == doctest::Approx(30.0f));
  const Aabb box = scene.objectBounds(1);
  CHECK(box.extent().x == doctest::Approx(6.0f));
  CHECK(box.min.y == doctest::Approx(0.0f));
  CHECK(box.center().x == doctest::Approx(0.0f));
  CHECK(box.center().z == doctest::Approx(0.0f));
  CHECK(scene.materials[scene.objects[1].material].texture ==
        cube.scene.materials[cube.scene.objects[0].material].texture);
  // A tall thin model: its height is the largest side.
  const Scene tent = placeOnGround(loadModelFile(kModels + "tent.obj"), 3.0f);
  CHECK(tent.objectBounds(1).extent().y == doctest::Approx(3.0f * 1.5f / 2.0f));
  CHECK(tent.objectBounds(1).extent().x == doctest::Approx(3.0f));
}

TEST_CASE("model: framed for the camera: its box's centre, its bounding sphere 45% of the view") {
  const float fovY = 0.873f;  // OrbitCamera's 50 degrees
  const Scene cube = placeOnGround(loadModelFile(kModels + "cube.obj"), 4.0f);
  const ModelFraming f = frameModel(cube, fovY);
  CHECK(f.target.x == doctest::Approx(0.0f));
  CHECK(f.target.y == doctest::Approx(2.0f));  // half of the 4 m cube standing on y = 0
  CHECK(f.target.z == doctest::Approx(0.0f));
  // The sphere through the cube's corners (radius 2 sqrt 3) seen under 45% of the half-angle's tangent.
  const float radius = 2.0f * std::sqrt(3.0f);
  CHECK(std::tan(std::asin(radius / f.distance)) == doctest::Approx(0.45f * std::tan(0.5f * fovY)));
  CHECK(f.distance == doctest::Approx(16.87f).epsilon(0.01));  // 2 sqrt 3 / sin(atan(0.45 tan 25 deg))
  // A tall model is framed at its middle height; a wider view comes closer.
  const Scene tent = placeOnGround(loadModelFile(kModels + "tent.obj"), 3.0f);
  CHECK(frameModel(tent, fovY).target.y == doctest::Approx(0.5f * tent.objectBounds(1).extent().y));
  CHECK(frameModel(cube, 1.2f).distance < f.distance);
  // Only the ground: nothing to frame, the default pose.
  Scene ground = cube;
  ground.objects.resize(1);
  CHECK(frameModel(ground, fovY).distance == doctest::Approx(1.0f));
}

TEST_CASE("model: the current model: each load a new generation, a failed load keeps the previous one") {
  const std::uint64_t before = currentModelGeneration();
  loadCurrentModel(kModels + "cube.obj");
  CHECK(currentModelGeneration() == before + 1);
  REQUIRE(currentModel() != nullptr);
  CHECK_THROWS_AS(loadCurrentModel(kModels + "empty.obj"), ModelError);
  CHECK(currentModelGeneration() == before + 1);
  CHECK(currentModel()->scene.name == "cube.obj");
  CHECK(analyseTopology(flatten(loadModelFile(kModels + "tent.obj").scene)).boundaryEdges == 4);
}

TEST_CASE("model: open meshes are drawn two-sided, closed ones keep back-face culling") {
  // Without it a wall seen from its open side was culled while the ground truth still hit it.
  const auto twoSided = [](const ModelFile& m, std::size_t object) {
    return m.scene.materials.at(m.scene.objects.at(object).material).twoSided;
  };
  const ModelFile chimney = loadModelFile(kModels + "chimney.obj");  // four walls, no top, no bottom
  REQUIRE(chimney.scene.objects.size() == 1);
  CHECK(twoSided(chimney, 0));
  CHECK(anyNote(chimney, "1 of 1 meshes are open (not closed 2-manifolds): drawn two-sided"));
  CHECK(twoSided(loadModelFile(kModels + "tent.obj"), 0));  // a pyramid without its floor
  for (const char* closed : {"cube.obj", "tetrahedron.glb", "no_normals.obj"}) {
    CAPTURE(closed);
    const ModelFile m = loadModelFile(kModels + closed);
    for (std::size_t i = 0; i < m.scene.objects.size(); ++i) CHECK_FALSE(twoSided(m, i));
    CHECK_FALSE(anyNote(m, "open"));
  }
  // One material shared by a closed tetrahedron and an open triangle: the open one gets a two-sided
  // copy, the closed one keeps the culled original.
  const std::string shared =
      "o closed\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"
      "o open\nv 3 0 0\nv 4 0 0\nv 3 1 0\nf 5 6 7\n";
  const ModelFile both = loadModelFromMemory(shared.data(), shared.size(), "obj");
  REQUIRE(both.scene.objects.size() == 2);
  std::size_t open = 0, closed = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    const bool isOpen = !analyseTopology(both.scene.meshes.at(both.scene.objects[i].mesh)).closed();
    (isOpen ? open : closed) = i;
  }
  REQUIRE(open != closed);
  CHECK(twoSided(both, open));
  CHECK_FALSE(twoSided(both, closed));
  CHECK(both.scene.objects[open].material != both.scene.objects[closed].material);
  CHECK(anyNote(both, "1 of 2 meshes are open"));
}

// What a file holds but cannot be drawn is said, never dropped in silence: triangles of no area
// (Assimp's number_formats.obj joins three collinear points), and the faces Assimp drops itself
// with only a warning (a glTF index past its vertices: the tetrahedron would have a hole).
TEST_CASE("model: triangles of no area and faces the importer drops are named in the notes") {
  const std::string line = "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n";
  std::string error;
  try {
    loadModelFromMemory(line.data(), line.size(), "obj", "collinear.obj");
  } catch (const ModelError& e) { error = e.what(); }
  CHECK(contains(error, "model 'collinear.obj': no triangles to draw (1 triangles of no area"));
  // (A face with two corners at one point Assimp turns into a line itself: FindDegenerates, a note.)
  const std::string mixed = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 2 4\nf 2 4 5\n";
  const ModelFile m = loadModelFromMemory(mixed.data(), mixed.size(), "obj", "mixed.obj");
  REQUIRE(m.scene.meshes.size() == 1);
  CHECK(m.scene.meshes[0].indices.size() == 3);  // the one triangle with an area
  CHECK(m.flatTriangles == 2);
  CHECK(anyNote(m, "dropped 2 triangles of no area (corners in a line or repeated): they draw nothing"));

  const ModelFile holed = loadModelFile(kModels + "bad_index.gltf");
  CHECK(anyNote(holed, "the importer (Assimp) warned: Some faces had out-of-range indices. Those faces were dropped."));
  const ModelFile whole = loadModelFile(kModels + "tetrahedron.gltf");
  CHECK_FALSE(anyNote(whole, "the importer (Assimp) warned"));
}

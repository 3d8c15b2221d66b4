// Procedural scenes: valid references, triangle counts near their targets, determinism per seed,
// and the properties each lesson relies on (alpha-tested leaves, a closed room, streets).
#include <doctest/doctest.h>

#include <initializer_list>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "core/mesh_gen.hpp"
#include "core/scene_gen.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

void checkConsistent(const Scene& scene) {
  REQUIRE_FALSE(scene.objects.empty());
  std::size_t badRefs = 0, badMatrices = 0, missingTextures = 0;
  for (const SceneObject& o : scene.objects) {
    badRefs += o.mesh >= scene.meshes.size() || o.material >= scene.materials.size();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) badMatrices += !std::isfinite(o.model[c][r]);
    badMatrices += o.model[3][3] != 1.0f;  // affine placements only
  }
  for (const Material& m : scene.materials)
    if (!m.texture.empty()) missingTextures += !std::filesystem::exists(test::sourceTree() + "/textures/" + m.texture);
  CHECK(badRefs == 0);
  CHECK(badMatrices == 0);
  CHECK(missingTextures == 0);
  for (const Mesh& m : scene.meshes) {
    CHECK(m.normals.size() == m.positions.size());
    CHECK(m.uvs.size() == m.positions.size());
    CHECK(std::all_of(m.indices.begin(), m.indices.end(), [&](std::uint32_t i) { return i < m.positions.size(); }));
  }
  const Aabb all = scene.bounds();
  REQUIRE_FALSE(all.empty());
  for (std::size_t i = 0; i < scene.objects.size(); i += 1 + scene.objects.size() / 64) {
    const Aabb b = scene.objectBounds(i);
    CHECK(glm::all(glm::greaterThanEqual(b.min, all.min)));
    CHECK(glm::all(glm::lessThanEqual(b.max, all.max)));
  }
}

bool sameScene(const Scene& a, const Scene& b) {
  if (a.objects.size() != b.objects.size() || a.meshes.size() != b.meshes.size()) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i)
    if (a.objects[i].model != b.objects[i].model || a.objects[i].mesh != b.objects[i].mesh ||
        a.objects[i].name != b.objects[i].name)
      return false;
  for (std::size_t i = 0; i < a.meshes.size(); ++i)
    if (a.meshes[i].positions != b.meshes[i].positions || a.meshes[i].indices != b.meshes[i].indices) return false;
  return true;
}

const SceneObject& objectNamed(const Scene& scene, const std::string& name) {
  for (const SceneObject& o : scene.objects)
    if (o.name == name) return o;
  FAIL("no object named " << name);
  return scene.objects.front();
}

}  // namespace

TEST_CASE("scene_gen: the five scenes, and unknown names listed in the error") {
  const std::vector<std::string> names = sceneNames();
  CHECK(names == std::vector<std::string>{"showcase", "city", "forest", "terrain", "room"});
  CHECK_THROWS_AS(makeScene("cathedral", 1, 10'000), std::invalid_argument);
  try {
    makeScene("cathedral", 1, 10'000);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    CHECK(message.find("cathedral") != std::string::npos);
    for (const std::string& n : names) CHECK(message.find(n) != std::string::npos);
  }
}

TEST_CASE("scene_gen: every scene is consistent and within a factor 1.5 of 10k and 100k triangles") {
  for (const std::string& name : sceneNames())
    for (std::size_t target : {std::size_t(10'000), std::size_t(100'000)}) {
      INFO(name << " at " << target);
      const Scene scene = makeScene(name, 3, target);
      CHECK(scene.name == name);
      checkConsistent(scene);
      const double tris = double(scene.triangleCount());
      CHECK(tris >= double(target) / 1.5);
      CHECK(tris <= double(target) * 1.5);
    }
}

TEST_CASE("scene_gen: 1M-triangle scenes reach their target") {
  for (const std::string& name : sceneNames()) {
    INFO(name);
    const Scene scene = makeScene(name, 5, 1'000'000);
    const double tris = double(scene.triangleCount());
    CHECK(tris >= 1e6 / 1.5);
    CHECK(tris <= 1e6 * 1.5);
  }
}

TEST_CASE("scene_gen: same seed same scene, different seed different scene") {
  for (const std::string& name : sceneNames()) {
    INFO(name);
    const Scene a = makeScene(name, 11, 10'000);
    CHECK(sameScene(a, makeScene(name, 11, 10'000)));
    CHECK_FALSE(sameScene(a, makeScene(name, 12, 10'000)));
  }
}

TEST_CASE("scene_gen: showcase shapes are closed and rest above the ground") {
  const Scene scene = makeScene("showcase", 1, 20'000);
  for (const std::string shape : {"box", "sphere", "torus", "knot"}) {
    INFO(shape);
    const SceneObject& o = objectNamed(scene, shape);
    CHECK(analyseTopology(scene.meshes[o.mesh]).closed());
    CHECK(scene.objectBounds(&o - scene.objects.data()).min.y >= -1e-3f);
  }
  const SceneObject& ground = objectNamed(scene, "ground");
  CHECK(scene.materials[ground.material].texture == "checker.png");
}

TEST_CASE("scene_gen: city blocks share one mesh, stand on the ground, leave streets between") {
  const Scene scene = makeScene("city", 2, 10'000);
  std::set<std::uint32_t> blockMeshes;
  std::vector<Aabb> blocks;
  float lowest = 1e30f, highest = 0.0f;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name.rfind("block", 0) != 0) continue;
    blockMeshes.insert(scene.objects[i].mesh);
    blocks.push_back(scene.objectBounds(i));
    lowest = std::min(lowest, blocks.back().max.y);
    highest = std::max(highest, blocks.back().max.y);
  }
  REQUIRE(blocks.size() >= 100);
  CHECK(blockMeshes.size() == 1);
  CHECK(highest > 2.0f * lowest);  // heights vary
  std::size_t floating = 0, overlapping = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    floating += std::abs(blocks[i].min.y) > 1e-4f;
    // Street width 4 on 10 m lots: any two blocks are at least 4 m apart along x or z.
    for (std::size_t j = i + 1; j < blocks.size(); ++j) {
      const float gapX = std::max(blocks[j].min.x - blocks[i].max.x, blocks[i].min.x - blocks[j].max.x);
      const float gapZ = std::max(blocks[j].min.z - blocks[i].max.z, blocks[i].min.z - blocks[j].max.z);
      overlapping += std::max(gapX, gapZ) < 4.0f - 1e-3f;
    }
  }
  CHECK(floating == 0);
  CHECK(overlapping == 0);
  const SceneObject& ground = objectNamed(scene, "ground");
  const Aabb groundBox = scene.objectBounds(&ground - scene.objects.data());
  for (const Aabb& b : blocks) {
    CHECK(b.min.x >= groundBox.min.x);
    CHECK(b.max.z <= groundBox.max.z);
  }
}

TEST_CASE("scene_gen: forest crowns and fence are alpha-tested two-sided cards") {
  const Scene scene = makeScene("forest", 4, 10'000);
  std::size_t crowns = 0, fences = 0, trunks = 0;
  for (const SceneObject& o : scene.objects) {
    const Material& m = scene.materials[o.material];
    if (o.name.rfind("crown", 0) == 0) {
      ++crowns;
      CHECK(m.texture == "leaves.png");
      CHECK(m.alphaCutoff == 0.5f);
      CHECK(m.twoSided);
    } else if (o.name.rfind("fence", 0) == 0) {
      ++fences;
      CHECK(m.alphaCutoff == 0.5f);
      CHECK(m.twoSided);
    } else if (o.name.rfind("trunk", 0) == 0) {
      ++trunks;
      CHECK(m.alphaCutoff == 0.0f);
      CHECK(analyseTopology(scene.meshes[o.mesh]).closed());
    }
  }
  CHECK(crowns >= 8);
  CHECK(crowns == trunks);
  CHECK(fences >= 8);
  // Crowns share a handful of meshes rather than one each.
  std::set<std::uint32_t> crownMeshes;
  for (const SceneObject& o : scene.objects)
    if (o.name.rfind("crown", 0) == 0) crownMeshes.insert(o.mesh);
  CHECK(crownMeshes.size() <= 3);
}

TEST_CASE("scene_gen: the room is closed and its shell faces inward") {
  const Scene scene = makeScene("room", 9, 10'000);
  const SceneObject& walls = objectNamed(scene, "walls and ceiling");
  const SceneObject& floor = objectNamed(scene, "floor");
  CHECK(scene.materials[walls.material].texture == "bricks.png");
  CHECK(scene.materials[floor.material].texture == "checker.png");
  Mesh shell;
  shell.append(scene.meshes[walls.mesh], walls.model);
  shell.append(scene.meshes[floor.mesh], floor.model);
  CHECK(analyseTopology(shell).closed());
  const glm::vec3 centre = shell.bounds().center();
  std::size_t outward = 0;
  for (std::size_t t = 0; t < shell.indices.size(); t += 3) {
    const glm::vec3 a = shell.positions[shell.indices[t]], b = shell.positions[shell.indices[t + 1]],
                    c = shell.positions[shell.indices[t + 2]];
    outward += glm::dot(glm::cross(b - a, c - a), centre - (a + b + c) / 3.0f) <= 0.0f;
  }
  CHECK(outward == 0);
  // Every other object lies inside the shell.
  const Aabb room = shell.bounds();
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Aabb b = scene.objectBounds(i);
    INFO(scene.objects[i].name);
    CHECK(glm::all(glm::greaterThanEqual(b.min, room.min - 1e-3f)));
    CHECK(glm::all(glm::lessThanEqual(b.max, room.max + 1e-3f)));
  }
}

TEST_CASE("scene_gen: terrain rocks are closed and sit on the height field") {
  const Scene scene = makeScene("terrain", 6, 10'000);
  const SceneObject& terrain = objectNamed(scene, "terrain");
  const Aabb ground = scene.objectBounds(&terrain - scene.objects.data());
  std::size_t rocks = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.name.rfind("rock", 0) != 0) continue;
    ++rocks;
    CHECK(analyseTopology(scene.meshes[o.mesh]).closed());
    const Aabb b = scene.objectBounds(i);
    CHECK(b.min.x >= ground.min.x);
    CHECK(b.max.x <= ground.max.x);
    CHECK(b.max.y > ground.min.y);
  }
  CHECK(rocks >= 3);
  CHECK(scene.materials[terrain.material].texture == "ground.png");
}

TEST_CASE("scene_gen: plain surfaces keep the cards' textures and take the others' mean colour") {
  for (const char* name : {"city", "forest", "showcase"}) {
    CAPTURE(name);
    const Scene textured = makeScene(name, 1, 10000);
    Scene plain = textured;
    makePlain(plain);
    REQUIRE(plain.materials.size() == textured.materials.size());
    int changed = 0;
    for (std::size_t i = 0; i < plain.materials.size(); ++i) {
      const Material &a = textured.materials[i], &b = plain.materials[i];
      CAPTURE(a.name);
      if (a.alphaCutoff > 0.0f || a.texture.empty()) {  // a card's holes are its shape; untextured stays
        CHECK(b.texture == a.texture);
        CHECK(b.albedo == a.albedo);
        continue;
      }
      ++changed;
      CHECK(b.texture.empty());
      for (int c = 0; c < 3; ++c) {  // the mean of a texture in linear light: darker than white, not black
        CHECK(b.albedo[c] < a.albedo[c]);
        CHECK(b.albedo[c] > 0.02f * a.albedo[c]);
      }
    }
    CHECK(changed > 0);  // every scene has a checker or brick surface
  }
}

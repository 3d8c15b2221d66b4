#include "core/scene_gen.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/image.hpp"
#include "core/mesh_gen.hpp"
#include "core/paths.hpp"

namespace shadowlab {

namespace {

constexpr float kPi = 3.14159265358979f;

// ---- tessellation from a triangle budget: each inverts its generator's count formula --------------
int planeCellsFor(double budget) { return std::max(1, int(std::lround(std::sqrt(budget / 2.0)))); }
int boxCellsFor(double budget) { return std::max(1, int(std::lround(std::sqrt(budget / 12.0)))); }
// Sphere with stacks = slices / 2: 2 s (s/2 - 1) = s^2 - 2s triangles.
int sphereSlicesFor(double budget) {
  const int s = int(std::lround(1.0 + std::sqrt(1.0 + std::max(budget, 0.0))));
  return std::max(8, s + (s & 1));
}
// Tubes with segments = ratio * sides: 2 ratio sides^2 triangles.
int tubeSidesFor(double budget, int ratio) { return std::max(4, int(std::lround(std::sqrt(budget / (2.0 * ratio))))); }

Mesh budgetSphere(float radius, double budget) {
  const int s = sphereSlicesFor(budget);
  return makeSphere(radius, s, s / 2);
}
Mesh budgetTorus(float R, float r, double budget) {
  const int sides = tubeSidesFor(budget, 3);
  return makeTorus(R, r, 3 * sides, sides);
}
Mesh budgetKnot(float radius, float tube, double budget) {
  const int sides = tubeSidesFor(budget, 8);
  return makeTorusKnot(2, 3, radius, tube, 8 * sides, sides);
}

glm::mat4 placed(const glm::vec3& at, float yaw = 0.0f, const glm::vec3& scale = glm::vec3(1.0f)) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
  m = glm::rotate(m, yaw, glm::vec3(0, 1, 0));
  return glm::scale(m, scale);
}

void addObject(Scene& scene, std::string name, std::uint32_t mesh, std::uint32_t material, const glm::mat4& model,
               bool castsShadow = true) {
  SceneObject o;
  o.name = std::move(name);
  o.mesh = mesh;
  o.material = material;
  o.model = model;
  o.castsShadow = castsShadow;
  scene.addObject(std::move(o));
}

Material material(std::string name, glm::vec3 albedo, std::string texture = {}, float specular = 0.25f,
                  float shininess = 32.0f) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  m.texture = std::move(texture);
  m.specular = specular;
  m.shininess = shininess;
  return m;
}

Material alphaTested(std::string name, std::string texture) {
  Material m = material(std::move(name), glm::vec3(1.0f), std::move(texture), 0.05f, 8.0f);
  m.alphaCutoff = 0.5f;
  m.twoSided = true;
  return m;
}

// ---- showcase: the lighting lesson's still life ---------------------------------------------------
Scene makeShowcase(std::uint64_t seed, double target) {
  Scene scene;
  SplitMix64 rng(seed);
  const auto ground = scene.addMaterial(material("checker ground", glm::vec3(0.85f), "checker.png", 0.1f, 16.0f));
  const auto bricks = scene.addMaterial(material("brick box", glm::vec3(1.0f), "bricks.png", 0.1f, 16.0f));
  const auto red = scene.addMaterial(material("red plastic", {0.8f, 0.15f, 0.12f}, {}, 0.6f, 64.0f));
  const auto gold = scene.addMaterial(material("gold", {0.9f, 0.7f, 0.25f}, {}, 0.8f, 96.0f));
  const auto blue = scene.addMaterial(material("blue ceramic", {0.2f, 0.35f, 0.85f}, {}, 0.5f, 48.0f));

  addObject(scene, "ground", scene.addMesh(makePlane(30.0f, planeCellsFor(0.15 * target), 10.0f)), ground,
            glm::mat4(1.0f), false);
  // Four shapes on a circle; the seed turns the circle and jitters each shape a little, so
  // randomised tests see varied but always sensible layouts.
  const float phase = rng.uniform(0.0f, 2.0f * kPi);
  auto spot = [&](int k, float height) {
    const float angle = phase + float(k) * 0.5f * kPi + rng.uniform(-0.15f, 0.15f);
    const float radius = 4.5f + rng.uniform(-0.5f, 0.5f);
    return glm::vec3(radius * std::cos(angle), height, radius * std::sin(angle));
  };
  // Spot first, then yaw, in separate statements: argument evaluation order is unspecified, and
  // the random sequence must not depend on the compiler.
  auto spotTurned = [&](int k, float height) {
    const glm::vec3 at = spot(k, height);
    return placed(at, rng.uniform(0.0f, kPi));
  };
  addObject(scene, "box", scene.addMesh(makeBox(glm::vec3(2.0f), boxCellsFor(0.05 * target))), bricks,
            spotTurned(0, 1.0f));
  addObject(scene, "sphere", scene.addMesh(budgetSphere(1.2f, 0.2 * target)), red, placed(spot(1, 1.2f)));
  // The torus stands tilted so its hole throws a shadow on the ground.
  const glm::mat4 torusModel = glm::rotate(spotTurned(2, 1.6f), 1.2f, glm::vec3(1, 0, 0));
  const auto torusMesh = scene.addMesh(budgetTorus(1.1f, 0.38f, 0.25 * target));
  addObject(scene, "torus", torusMesh, gold, torusModel);
  // Rest it on the ground: lift it by whatever its tilted bounds reach below y = 0.
  const float sink = scene.objectBounds(scene.objects.size() - 1).min.y;
  if (sink < 0.0f) scene.objects.back().model = glm::translate(glm::mat4(1.0f), glm::vec3(0, -sink, 0)) * torusModel;
  addObject(scene, "knot", scene.addMesh(budgetKnot(1.5f, 0.32f, 0.35 * target)), blue, spotTurned(3, 2.3f));
  return scene;
}

// ---- city: blocks on a street grid ----------------------------------------------------------------
Scene makeCity(std::uint64_t seed, double target) {
  Scene scene;
  SplitMix64 rng(seed);
  // Blocks stay few (at most 48 x 48, a draw call each) and gain facade tessellation instead, so
  // a 1M-triangle city is still a few thousand objects. Smallest s whose grid fits decides both.
  constexpr int kMaxGrid = 48;
  const double blockBudget = 0.95 * target;
  int cells = 1, grid = 1;
  for (;; ++cells) {
    grid = std::max(2, int(std::lround(std::sqrt(blockBudget / (12.0 * cells * cells)))));
    if (grid <= kMaxGrid) break;
  }
  const float lot = 10.0f, street = 4.0f;
  const float extent = grid * lot;
  const auto asphalt = scene.addMaterial(material("street", glm::vec3(0.55f), "checker.png", 0.05f, 8.0f));
  const auto facade = scene.addMaterial(material("facade", glm::vec3(0.95f), "bricks.png", 0.1f, 16.0f));
  const auto groundMesh = scene.addMesh(makePlane(extent + 2.0f * street, planeCellsFor(0.03 * target), grid * 2.0f));
  addObject(scene, "ground", groundMesh, asphalt, glm::mat4(1.0f), false);
  const auto block = scene.addMesh(makeBox(glm::vec3(1.0f), cells));  // unit box, scaled per block
  scene.objects.reserve(scene.objects.size() + std::size_t(grid) * grid);
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const float u = rng.uniform();
      // Mostly low blocks with a few towers: the tall ones make long shadows across streets.
      const float height = 3.0f + 45.0f * u * u * u;
      const float width = lot - street - rng.uniform(0.0f, 1.5f);
      const float depth = lot - street - rng.uniform(0.0f, 1.5f);
      const glm::vec3 centre{(float(i) + 0.5f) * lot - 0.5f * extent, 0.5f * height,
                             (float(j) + 0.5f) * lot - 0.5f * extent};
      addObject(scene, "block " + std::to_string(i) + "," + std::to_string(j), block, facade,
                placed(centre, 0.0f, {width, height, depth}));
    }
  return scene;
}

// ---- forest: trunks, leaf-card crowns, a fence --------------------------------------------------
Mesh makeCrown(SplitMix64& rng, int cards) {
  Mesh crown;
  const Mesh card = makeCard(1.4f, 1.4f);
  crown.positions.reserve(std::size_t(cards) * 4);
  crown.normals.reserve(std::size_t(cards) * 4);
  crown.uvs.reserve(std::size_t(cards) * 4);
  crown.indices.reserve(std::size_t(cards) * 6);
  for (int k = 0; k < cards; ++k) {
    // Uniform in an ellipsoid (rejection keeps it exact and deterministic).
    glm::vec3 p;
    do p = {rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)};
    while (glm::dot(p, p) > 1.0f);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), p * glm::vec3(2.2f, 1.8f, 2.2f));
    m = glm::rotate(m, rng.uniform(0.0f, 2.0f * kPi), glm::vec3(0, 1, 0));
    m = glm::rotate(m, rng.uniform(-0.9f, 0.9f), glm::vec3(1, 0, 0));
    crown.append(card, glm::translate(m, glm::vec3(0.0f, -0.7f, 0.0f)));  // centre the card
  }
  return crown;
}

Scene makeForest(std::uint64_t seed, double target) {
  Scene scene;
  SplitMix64 rng(seed);
  const float size = 80.0f, hills = 4.0f;
  const std::uint64_t terrainSeed = rng.next();
  const auto ground = scene.addMaterial(material("forest floor", glm::vec3(1.0f), "ground.png", 0.05f, 8.0f));
  const auto bark = scene.addMaterial(material("bark", {0.35f, 0.25f, 0.17f}, {}, 0.05f, 8.0f));
  const auto leaves = scene.addMaterial(alphaTested("leaves", "leaves.png"));
  const auto fenceMaterial = scene.addMaterial(alphaTested("fence", "fence.png"));

  addObject(scene, "terrain", scene.addMesh(makeTerrain(size, planeCellsFor(0.15 * target), hills, terrainSeed)),
            ground, glm::mat4(1.0f));
  auto groundAt = [&](float x, float z) { return terrainHeight(x, z, size, hills, terrainSeed); };

  // A paddock fence: panels of a fixed 2 m so it reads as a fence at every scale.
  const int panelsPerSide = 6;
  const float fenceHalf = float(panelsPerSide);  // 2 m panels, centred
  const auto panel = scene.addMesh(makeCard(2.0f, 1.2f));
  const glm::vec2 fenceCentre{rng.uniform(-20.0f, 20.0f), rng.uniform(-20.0f, 20.0f)};
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < panelsPerSide; ++k) {
      const float along = (float(k) + 0.5f) * 2.0f - fenceHalf;
      glm::vec2 offset = side == 0   ? glm::vec2(along, -fenceHalf)
                         : side == 1 ? glm::vec2(fenceHalf, along)
                         : side == 2 ? glm::vec2(-along, fenceHalf)
                                     : glm::vec2(-fenceHalf, -along);
      const glm::vec2 at = fenceCentre + offset;
      addObject(scene, "fence " + std::to_string(side * panelsPerSide + k), panel, fenceMaterial,
                placed({at.x, groundAt(at.x, at.y) - 0.1f, at.y}, -0.5f * kPi * float(side)));
    }

  const int trees = std::clamp(int(std::lround(std::sqrt(target) / 5.0)), 8, 300);
  const int trunkSegments = 12;
  const auto trunk = scene.addMesh(makeCylinder(0.22f, 1.0f, trunkSegments, true));  // unit height
  const double trunkTris = 4.0 * trunkSegments;
  const double perTree = (0.85 * target - 2.0 * 4 * panelsPerSide) / trees;
  const int cards = std::max(8, int(std::lround((perTree - trunkTris) / 2.0)));
  // Three crown shapes shared by all trees: variety without a mesh per tree.
  std::uint32_t crowns[3];
  for (std::uint32_t& c : crowns) c = scene.addMesh(makeCrown(rng, cards));
  for (int t = 0; t < trees; ++t) {
    const float x = rng.uniform(-0.45f, 0.45f) * size, z = rng.uniform(-0.45f, 0.45f) * size;
    const float y = groundAt(x, z);
    const float height = rng.uniform(3.0f, 6.0f), scale = rng.uniform(0.8f, 1.25f);
    const float yaw = rng.uniform(0.0f, 2.0f * kPi);
    // Trunks sink 0.3 m so slopes never show a gap under them.
    addObject(scene, "trunk " + std::to_string(t), trunk, bark,
              placed({x, y - 0.3f + 0.5f * (height + 0.3f), z}, yaw, {1.0f, height + 0.3f, 1.0f}));
    addObject(scene, "crown " + std::to_string(t), crowns[rng.below(3)], leaves,
              placed({x, y + height + 1.2f * scale, z}, yaw, glm::vec3(scale)));
  }
  return scene;
}

// ---- terrain: a large height field with rocks ---------------------------------------------------
Mesh makeRock(SplitMix64& rng, double budget) {
  Mesh rock = budgetSphere(1.0f, budget);
  const std::uint64_t seed = rng.next();
  // Displacement is a function of the direction alone, so seam copies move together and the
  // rock stays closed.
  for (glm::vec3& p : rock.positions) {
    const float bump = 0.5f * fbmNoise(2.0f * p.x + 7.0f, 2.0f * p.y + 3.0f * p.z, 4, seed) +
                       0.5f * fbmNoise(2.0f * p.z - 5.0f, 2.0f * p.y - 3.0f * p.x, 4, seed + 1);
    p *= 0.7f + 0.6f * bump;
  }
  computeSmoothNormals(rock);
  return rock;
}

Scene makeTerrainScene(std::uint64_t seed, double target) {
  Scene scene;
  SplitMix64 rng(seed);
  const float size = 200.0f, hills = 20.0f;
  const std::uint64_t terrainSeed = rng.next();
  const auto ground = scene.addMaterial(material("grass and dirt", glm::vec3(1.0f), "ground.png", 0.05f, 8.0f));
  const auto stone = scene.addMaterial(material("rock", {0.5f, 0.48f, 0.45f}, {}, 0.15f, 16.0f));
  addObject(scene, "terrain", scene.addMesh(makeTerrain(size, planeCellsFor(0.85 * target), hills, terrainSeed)),
            ground, glm::mat4(1.0f));
  const int rocks = 12;
  std::uint32_t shapes[3];
  for (std::uint32_t& s : shapes) s = scene.addMesh(makeRock(rng, 0.15 * target / rocks));
  for (int r = 0; r < rocks; ++r) {
    const float x = rng.uniform(-0.4f, 0.4f) * size, z = rng.uniform(-0.4f, 0.4f) * size;
    const float scale = rng.uniform(1.5f, 5.0f);
    const glm::vec3 stretch{scale * rng.uniform(0.8f, 1.4f), scale * rng.uniform(0.5f, 0.9f),
                            scale * rng.uniform(0.8f, 1.4f)};
    // Half buried, as rocks are.
    addObject(scene, "rock " + std::to_string(r), shapes[rng.below(3)], stone,
              placed({x, terrainHeight(x, z, size, hills, terrainSeed), z}, rng.uniform(0.0f, 2.0f * kPi), stretch));
  }
  return scene;
}

// ---- room: a closed shell seen from inside ------------------------------------------------------
// The faces of makeBox come in the order +x, -x, +z, -z, +y, -y, each (n+1)^2 vertices.
Mesh boxFaces(const Mesh& box, int firstFace, int faceCount, int cells) {
  const std::size_t verts = std::size_t(cells + 1) * (cells + 1), tris = std::size_t(2) * cells * cells;
  Mesh out;
  const std::size_t v0 = verts * firstFace, v1 = verts * (firstFace + faceCount);
  out.positions.assign(box.positions.begin() + v0, box.positions.begin() + v1);
  out.normals.assign(box.normals.begin() + v0, box.normals.begin() + v1);
  out.uvs.assign(box.uvs.begin() + v0, box.uvs.begin() + v1);
  for (std::size_t i = tris * 3 * firstFace; i < tris * 3 * (firstFace + faceCount); ++i)
    out.indices.push_back(box.indices[i] - std::uint32_t(v0));
  return out;
}

Scene makeRoom(std::uint64_t seed, double target) {
  Scene scene;
  SplitMix64 rng(seed);
  const glm::vec3 room{12.0f, 5.0f, 12.0f};
  const auto wallMaterial = scene.addMaterial(material("brick walls", glm::vec3(1.0f), "bricks.png", 0.1f, 16.0f));
  const auto floorMaterial = scene.addMaterial(material("checker floor", glm::vec3(0.9f), "checker.png", 0.2f, 32.0f));
  const auto white = scene.addMaterial(material("white", glm::vec3(0.85f), {}, 0.3f, 32.0f));
  const auto red = scene.addMaterial(material("red", {0.8f, 0.15f, 0.12f}, {}, 0.6f, 64.0f));
  const auto blue = scene.addMaterial(material("blue", {0.2f, 0.35f, 0.85f}, {}, 0.5f, 48.0f));
  const auto gold = scene.addMaterial(material("gold", {0.9f, 0.7f, 0.25f}, {}, 0.8f, 96.0f));

  // One box turned inside out, split so the floor can carry its own material; together the two
  // meshes are closed, which shadow volumes and point-light cube maps rely on.
  const int cells = boxCellsFor(0.2 * target);
  Mesh shell = makeBox(room, cells);
  flipInsideOut(shell);
  const glm::mat4 shellModel = placed({0.0f, 0.5f * room.y, 0.0f});
  addObject(scene, "walls and ceiling", scene.addMesh(boxFaces(shell, 0, 5, cells)), wallMaterial, shellModel);
  addObject(scene, "floor", scene.addMesh(boxFaces(shell, 5, 1, cells)), floorMaterial, shellModel);

  auto jitter = [&](float x, float z) {
    return glm::vec3(x + rng.uniform(-0.6f, 0.6f), 0.0f, z + rng.uniform(-0.6f, 0.6f));
  };
  glm::vec3 at = jitter(-2.5f, -2.5f);
  addObject(scene, "box", scene.addMesh(makeBox(glm::vec3(1.6f), boxCellsFor(0.05 * target))), white,
            placed(at + glm::vec3(0, 0.8f, 0), rng.uniform(0.0f, kPi)));
  at = jitter(2.5f, -2.0f);
  addObject(scene, "sphere", scene.addMesh(budgetSphere(1.0f, 0.25 * target)), red, placed(at + glm::vec3(0, 1.0f, 0)));
  at = jitter(0.0f, 2.5f);
  addObject(scene, "knot", scene.addMesh(budgetKnot(1.2f, 0.28f, 0.3 * target)), blue,
            placed(at + glm::vec3(0, 1.8f, 0), rng.uniform(0.0f, kPi)));
  at = jitter(-3.0f, 2.5f);
  glm::mat4 torusModel =
      glm::rotate(placed(at + glm::vec3(0, 0.95f, 0), rng.uniform(0.0f, kPi)), 0.5f * kPi, glm::vec3(1, 0, 0));
  addObject(scene, "torus", scene.addMesh(budgetTorus(0.7f, 0.25f, 0.15 * target)), gold, torusModel);
  // Two pillars floor to ceiling: casters the light cannot get around.
  const int pillarSegments = std::max(8, int(std::lround(0.05 * target / 8.0)));
  const auto pillar = scene.addMesh(makeCylinder(0.3f, room.y, pillarSegments, true));
  addObject(scene, "pillar 0", pillar, white, placed({3.5f, 0.5f * room.y, 3.5f}));
  addObject(scene, "pillar 1", pillar, white, placed({-4.0f, 0.5f * room.y, -0.5f}));
  return scene;
}

}  // namespace

std::vector<std::string> sceneNames() { return {"showcase", "city", "forest", "terrain", "room"}; }

Scene makeScene(const std::string& name, std::uint64_t seed, std::size_t targetTriangles) {
  const double target = double(std::clamp<std::size_t>(targetTriangles, 1'000, 16'000'000));
  // Each scene draws from its own stream so one seed gives unrelated layouts across scenes.
  // FNV-1a rather than std::hash, whose values differ between standard libraries.
  std::uint64_t nameHash = 0xCBF29CE484222325ull;
  for (unsigned char c : name) nameHash = (nameHash ^ c) * 0x100000001B3ull;
  const std::uint64_t salted = SplitMix64(seed ^ nameHash).next();
  Scene scene;
  if (name == "showcase") scene = makeShowcase(salted, target);
  else if (name == "city") scene = makeCity(salted, target);
  else if (name == "forest") scene = makeForest(salted, target);
  else if (name == "terrain") scene = makeTerrainScene(salted, target);
  else if (name == "room") scene = makeRoom(salted, target);
  else {
    std::string valid;
    for (const std::string& n : sceneNames()) valid += (valid.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown scene '" + name + "'; valid scenes: " + valid);
  }
  scene.name = name;
  return scene;
}

void makePlain(Scene& scene) {
  for (Material& m : scene.materials) {
    if (m.texture.empty() || m.alphaCutoff > 0.0f) continue;
    const Image8 image = loadImage(texturePath(m.texture), 3);
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i + 2 < image.data.size(); i += 3)
      for (int c = 0; c < 3; ++c) {
        const double v = image.data[i + std::size_t(c)] / 255.0;  // sRGB, as the GPU decodes it
        sum[c] += v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
      }
    const double pixels = double(image.data.size() / 3);
    m.albedo *= glm::vec3(sum / std::max(pixels, 1.0));
    m.texture.clear();
  }
}

}  // namespace shadowlab

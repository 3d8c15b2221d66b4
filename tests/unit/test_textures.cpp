// Course textures: the PNGs committed under textures/ decode to exactly what the generators
// produce now, so anyone can regenerate them; and each texture has the property it is used for.
#include <doctest/doctest.h>

#include <initializer_list>

#include <set>

#include "core/image.hpp"
#include "core/texture_gen.hpp"
#include "test_support.hpp"

using namespace shadowlab;

TEST_CASE("textures: committed PNGs are reproducible byte for byte") {
  const auto textures = generateCourseTextures();
  std::set<std::string> names;
  for (const auto& [name, image] : textures) names.insert(name);
  CHECK(names == std::set<std::string>{"checker.png", "checker_fine.png", "bricks.png", "bricks_normal.png",
                                       "leaves.png", "ground.png", "text.png", "fence.png"});
  for (const auto& [name, generated] : textures) {
    const std::string& shown = name;  // INFO captures in a lambda: not a structured binding (clang 14)
    INFO(shown);
    CHECK((generated.width == 256 || generated.width == 512));
    CHECK(generated.height == generated.width);
    const Image8 committed = loadImage(test::sourceTree() + "/textures/" + name, generated.channels);
    REQUIRE(committed.width == generated.width);
    REQUIRE(committed.height == generated.height);
    const ImageDiff diff = compareImages(committed, generated);
    CHECK(diff.maxAbs == 0);
    CHECK(committed.data == generated.data);
  }
}

TEST_CASE("textures: generators are deterministic and seed-dependent") {
  CHECK(makeGroundTexture(64, 5).data == makeGroundTexture(64, 5).data);
  CHECK(makeGroundTexture(64, 5).data != makeGroundTexture(64, 6).data);
  CHECK(makeLeavesTexture(64, 5).data == makeLeavesTexture(64, 5).data);
  CHECK(makeLeavesTexture(64, 5).data != makeLeavesTexture(64, 6).data);
}

TEST_CASE("textures: checker squares by formula") {
  const Image8 c = makeCheckerTexture(64, 8, {255, 0, 0}, {0, 0, 255});
  REQUIRE(c.channels == 3);
  // 8 px squares: (x/8 + y/8) even is colour a.
  CHECK(c.at(0, 0)[0] == 255);
  CHECK(c.at(7, 7)[0] == 255);
  CHECK(c.at(8, 0)[2] == 255);
  CHECK(c.at(8, 8)[0] == 255);
  CHECK(c.at(63, 0)[2] == 255);
}

TEST_CASE("textures: alpha-tested textures have holes and solid parts") {
  for (const Image8& image : {makeLeavesTexture(256, 23), makeFenceTexture(256)}) {
    REQUIRE(image.channels == 4);
    std::size_t transparent = 0, opaque = 0;
    for (std::size_t i = 3; i < image.data.size(); i += 4) {
      transparent += image.data[i] == 0;
      opaque += image.data[i] == 255;
    }
    const std::size_t pixels = image.data.size() / 4;
    CHECK(transparent > pixels / 10);
    CHECK(opaque > pixels / 10);
  }
}

TEST_CASE("textures: the bricks normal map holds unit normals facing out of the surface") {
  const Image8 n = makeBricksNormalTexture(128, 17);
  std::size_t notUnit = 0, tilted = 0;
  for (std::size_t i = 0; i < n.data.size(); i += 3) {
    const glm::vec3 v = glm::vec3(n.data[i], n.data[i + 1], n.data[i + 2]) / 127.5f - 1.0f;
    notUnit += std::abs(glm::length(v) - 1.0f) > 0.02f;  // 8-bit quantisation tolerance
    CHECK(v.z > 0.0f);
    tilted += v.z < 0.95f;
  }
  CHECK(notUnit == 0);
  CHECK(tilted > 0);  // the brick bevels show
}

TEST_CASE("textures: text is mostly paper with dark marks") {
  const Image8 t = makeTextTexture(256, 41);
  std::size_t dark = 0;
  for (std::size_t i = 0; i < t.data.size(); i += 3) dark += t.data[i] < 64;
  const std::size_t pixels = t.data.size() / 3;
  CHECK(dark > pixels / 20);
  CHECK(dark < pixels / 2);
}

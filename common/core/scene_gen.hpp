#pragma once
// Procedural scenes shared by every lesson, test and benchmark. Deterministic: the same name, seed
// and target give the same scene, byte for byte, on the same platform. The target sets the size:
// each scene scales its tessellation and instance counts so that Scene::triangleCount() lands
// within a factor 1.5 of `targetTriangles` for targets from 10k to 1M (targets are clamped to
// [1k, 16M]; outside [10k, 1M] the factor is not promised).
//
//   showcase  ground plane, box, sphere, torus and torus knot: the lighting lesson's scene
//   city      ground and a grid of box blocks of random heights with streets between
//   forest    terrain, cylinder trunks with crowns of alpha-tested leaf cards, a card fence
//   terrain   a large fBm height field with a few rocks
//   room      a closed room (walls, ceiling and floor face inward) with objects inside
//
// Units are metres, y up, the ground near y = 0. Meshes are shared between instances where
// natural (blocks, trunks, crowns, rocks); each SceneObject carries its own model matrix.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace shadowlab {

inline constexpr std::size_t kDefaultSceneTriangles = 100'000;

// Throws std::invalid_argument for an unknown name; the message lists the valid names.
Scene makeScene(const std::string& name, std::uint64_t seed = 1, std::size_t targetTriangles = kDefaultSceneTriangles);
// The names makeScene accepts, in the order lessons list them.
std::vector<std::string> sceneNames();
// Plain surfaces (scene.plain): every opaque material loses its texture and takes the texture's
// mean colour (averaged in linear light) times its own albedo, so bricks and checkerboards no
// longer compete with the shadows on a projector. Alpha-tested materials (leaf cards, fences) keep
// theirs: their holes are the shape. Throws std::runtime_error naming a texture that cannot load.
void makePlain(Scene& scene);

}  // namespace shadowlab

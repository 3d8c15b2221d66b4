#pragma once
// Lesson 06's three scenes, each the place where one side of filtering shows: a ground plane to the
// horizon (every level of detail at once), a tunnel seen down its axis (footprints stretched along
// it: anisotropy), a sphere (the projections' seams and poles); and the texture coordinates each
// has by nature, tiled so that texels stay roughly square.
#include <array>

#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh_gen.hpp"
#include "gl/mesh_gpu.hpp"

namespace lesson06 {

enum class SceneKind { Ground, Tunnel, Sphere };
enum class UvMode { Auto, Explicit, Planar, Cylindrical, Spherical };

struct Shape {
  shadowlab::gl::GpuMesh mesh;
  glm::mat4 model{1.0f};
};

// One per SceneKind: a 400 m plane, a tunnel of radius 3 m and 200 m along z (seen from inside), a
// sphere of radius 2 m centred 1 m above the ground.
inline std::array<Shape, 3> makeShapes() {
  using namespace shadowlab;
  Mesh tube = makeCylinder(3.0f, 200.0f, 96, false);
  flipInsideOut(tube);
  return {Shape{gl::uploadMesh(makePlane(400.0f, 8, 400.0f), "ground plane")},
          Shape{gl::uploadMesh(tube, "tunnel"), glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(1, 0, 0))},
          Shape{gl::uploadMesh(makeSphere(2.0f, 128, 64), "sphere"), glm::translate(glm::mat4(1), glm::vec3(0, 1, 0))}};
}

// `chosen`, or for Auto the scene's natural projection.
inline UvMode uvMode(UvMode chosen, SceneKind scene) {
  if (chosen != UvMode::Auto) return chosen;
  return scene == SceneKind::Ground   ? UvMode::Planar
         : scene == SceneKind::Tunnel ? UvMode::Cylindrical
                                      : UvMode::Spherical;
}

// Repeats of the texture along (u, v) at uv.scale 1 for a projection on a scene.
inline glm::vec2 uvTiling(UvMode mode, SceneKind scene) {
  if (mode == UvMode::Cylindrical) return {16.0f, 1.0f};
  if (mode == UvMode::Spherical) return {8.0f, 4.0f};
  if (mode == UvMode::Explicit && scene == SceneKind::Tunnel) return {16.0f, 200.0f / 18.85f * 16.0f};
  if (mode == UvMode::Explicit && scene == SceneKind::Sphere) return {8.0f, 4.0f};
  return glm::vec2(1.0f);
}

}  // namespace lesson06

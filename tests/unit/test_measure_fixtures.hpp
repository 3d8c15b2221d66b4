#pragma once
// Hand-built triangle scenes for the measure tests: they must not depend on core's mesh generators,
// so each analytic scene is made here from its definition.
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "core/scene.hpp"

namespace shadowlab::measure::test {

// An axis-aligned horizontal rectangle at height y over [x0,x1] x [z0,z1], normal +y (CCW seen from
// above), uv = ((x - x0) / (x1 - x0), (z - z0) / (z1 - z0)).
inline Mesh horizontalQuad(float x0, float x1, float z0, float z1, float y) {
  Mesh m;
  m.positions = {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A UV sphere whose vertices all lie on the sphere: `segments` around y, `rings` from pole to pole.
inline Mesh uvSphere(glm::vec3 centre, float radius, int segments, int rings) {
  const float pi = 3.14159265358979f;
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    float theta = pi * float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      float phi = 2 * pi * float(s) / float(segments);
      glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      m.positions.push_back(centre + radius * n);
      m.normals.push_back(n);
      m.uvs.push_back({float(s) / segments, float(r) / rings});
    }
  }
  auto id = [&](int r, int s) { return std::uint32_t(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      m.indices.insert(m.indices.end(), {id(r, s), id(r + 1, s), id(r + 1, s + 1)});
      m.indices.insert(m.indices.end(), {id(r, s), id(r + 1, s + 1), id(r, s + 1)});
    }
  return m;
}

inline void addObject(Scene& scene, Mesh mesh, std::uint32_t material = 0, bool casts = true) {
  SceneObject object;
  object.name = "object" + std::to_string(scene.objects.size());
  object.mesh = std::uint32_t(scene.meshes.size());
  object.material = material;
  object.castsShadow = casts;
  scene.meshes.push_back(std::move(mesh));
  scene.objects.push_back(object);
}

inline Material plainMaterial() {
  Material m;
  m.name = "plain";
  return m;
}

}  // namespace shadowlab::measure::test

// OBJ text through the model loader (core/model_file, Assimp, from memory as
// aiImportFileFromMemory reads it): a scene whose indices, normals and uvs are consistent and
// finite, or ModelError. The corpus (seeds and regressions) is the former hand-written parser's.
#include <cmath>

#include "core/model_file.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const ModelFile model = loadModelFromMemory(data, size, "obj", "fuzz.obj");
    FUZZ_CHECK(!model.scene.objects.empty());
    for (const SceneObject& o : model.scene.objects)
      FUZZ_CHECK(o.mesh < model.scene.meshes.size() && o.material < model.scene.materials.size());
    for (const Mesh& m : model.scene.meshes) {
      FUZZ_CHECK(!m.indices.empty() && m.indices.size() % 3 == 0);
      FUZZ_CHECK(m.normals.size() == m.positions.size() && m.uvs.size() == m.positions.size());
      for (std::uint32_t i : m.indices) FUZZ_CHECK(i < m.positions.size());
      for (std::size_t i = 0; i < m.positions.size(); ++i) {
        FUZZ_CHECK(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) &&
                   std::isfinite(m.positions[i].z));
        FUZZ_CHECK(std::abs(glm::length(m.normals[i]) - 1.0f) < 1e-3f);
        FUZZ_CHECK(std::isfinite(m.uvs[i].x) && std::isfinite(m.uvs[i].y));
      }
    }
  } catch (const ModelError&) {}
  return 0;
}

// OBJ text (core/obj_loader): a mesh whose indices, normals and uvs are consistent and finite, or
// std::runtime_error.
#include <cmath>
#include <stdexcept>

#include "core/obj_loader.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const Mesh m = parseObj(fuzz::text(data, size));
    FUZZ_CHECK(!m.indices.empty() && m.indices.size() % 3 == 0);
    FUZZ_CHECK(m.normals.size() == m.positions.size() && m.uvs.size() == m.positions.size());
    for (std::uint32_t i : m.indices) FUZZ_CHECK(i < m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      FUZZ_CHECK(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) && std::isfinite(m.positions[i].z));
      FUZZ_CHECK(std::abs(glm::length(m.normals[i]) - 1.0f) < 1e-3f);
      FUZZ_CHECK(std::isfinite(m.uvs[i].x) && std::isfinite(m.uvs[i].y));
    }
  } catch (const std::runtime_error&) {}
  return 0;
}

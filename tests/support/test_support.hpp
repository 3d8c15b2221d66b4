#pragma once
// Shared helpers for every test binary: the seed of randomised cases (grading/cases.hpp) and the
// checks that print inputs, expected, actual and tolerance (grading/checks.hpp).
#include <cstdint>
#include <random>
#include <string>

#include <glm/glm.hpp>

#include "grading/cases.hpp"
#include "grading/checks.hpp"

namespace shadowlab::test {

// The seed for randomised cases: --seed=N on the test binary's command line, else the
// SHADOWLAB_SEED environment variable, else a fixed default. Printed once per run so a failure
// can be replayed with the same seed.
inline std::uint64_t seed() { return grading::seed(); }

// A seed derived from the run's seed and a case-local salt, so cases stay independent.
inline std::uint64_t seedFor(const std::string& salt) { return grading::seedFor(salt); }

// The source tree and the unit tests' fixtures (tests/data) as configured, not moved by
// SHADOWLAB_ROOT. The absolute paths reach only test_paths.cpp, so every other test file compiles
// the same in any checkout (a compiler-cache hit from another one; see the top-level CMakeLists.txt).
std::string sourceTree();
std::string testData();

// A uniformly distributed unit vector.
inline glm::vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<float> n;
  glm::vec3 v;
  do v = {n(rng), n(rng), n(rng)};
  while (glm::length(v) < 1e-3f);
  return glm::normalize(v);
}

}  // namespace shadowlab::test

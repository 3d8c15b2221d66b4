#pragma once
// Shared helpers for every test binary.
#include <cstdint>
#include <string>

namespace shadowlab::test {

// The seed for randomised cases: --seed=N on the test binary's command line, else the
// SHADOWLAB_SEED environment variable, else a fixed default. Printed once per run so a failure
// can be replayed with the same seed.
std::uint64_t seed();

// A seed derived from the run's seed and a case-local salt, so cases stay independent.
std::uint64_t seedFor(const std::string& salt);

}  // namespace shadowlab::test

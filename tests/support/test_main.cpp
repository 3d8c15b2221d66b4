// The main() of every doctest binary: strips our own --seed=N flag, then hands over to doctest.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {
std::uint64_t g_seed = 20261122;
}

namespace shadowlab::test {
std::uint64_t seed() { return g_seed; }
std::uint64_t seedFor(const std::string& salt) {
  return g_seed ^ (std::hash<std::string>{}(salt) * 0x9E3779B97F4A7C15ull);
}
}  // namespace shadowlab::test

static bool parseSeed(const char* text, std::uint64_t& out) {
  char* end = nullptr;
  unsigned long long v = std::strtoull(text, &end, 10);
  if (end == text || *end != '\0') return false;
  out = v;
  return true;
}

int main(int argc, char** argv) {
  if (const char* env = std::getenv("SHADOWLAB_SEED")) {
    if (!parseSeed(env, g_seed)) {
      std::cerr << "SHADOWLAB_SEED='" << env << "' is not a non-negative integer\n";
      return 2;
    }
  }
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--seed=", 7) == 0) {
      if (!parseSeed(argv[i] + 7, g_seed)) {
        std::cerr << "--seed='" << (argv[i] + 7) << "' is not a non-negative integer\n";
        return 2;
      }
      continue;
    }
    rest.push_back(argv[i]);
  }
  doctest::Context context(static_cast<int>(rest.size()), rest.data());
  bool listing = false;  // test discovery parses stdout: print nothing extra then
  for (char* arg : rest) listing = listing || std::strncmp(arg, "--list", 6) == 0 || std::strncmp(arg, "-l", 2) == 0;
  if (!listing)
    std::cout << "[shadowlab] seed " << g_seed << " (replay with --seed=" << g_seed
              << " or SHADOWLAB_SEED)\n";
  return context.run();
}

#pragma once
// Shared by the libFuzzer targets in this folder (tests/fuzz.cmake builds them with clang,
// -fsanitize=fuzzer,address,undefined). Each target feeds one GL-free parser arbitrary bytes: a
// parser may refuse them with its documented exception, never crash, hang, leak or break the
// invariants checked with FUZZ_CHECK.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#define FUZZ_CHECK(condition)                                                                  \
  do {                                                                                         \
    if (!(condition)) {                                                                        \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
      std::abort();                                                                            \
    }                                                                                          \
  } while (false)

namespace shadowlab::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Splits at `separator`, keeping empty pieces, at most `limit` pieces (the rest stays in the last).
inline std::vector<std::string> split(const std::string& s, char separator, std::size_t limit = 1u << 20) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (out.size() + 1 < limit) {
    const std::size_t end = s.find(separator, start);
    if (end == std::string::npos) break;
    out.push_back(s.substr(start, end - start));
    start = end + 1;
  }
  out.push_back(s.substr(start));
  return out;
}

}  // namespace shadowlab::fuzz

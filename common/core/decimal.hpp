#pragma once
// A finite decimal number and nothing else, for every parser of the course (parameters, paths):
// "1.5", "-2e-3" and ".5" parse; "", "+1", " 1", "1x", "0x10", "nan", "inf" and values past the
// type's range do not. std::from_chars where the standard library has it for floating point
// (GCC's, MSVC's); the browser build's libc++ (emscripten 3.1.6) lacks it, and takes
// parseDecimalFallback, which refuses the same inputs (tests/unit/test_decimal.cpp holds the two
// to the same answers).
#include <string>
#include <string_view>

namespace shadowlab {

bool parseDecimal(std::string_view text, float& out);
bool parseDecimal(std::string_view text, double& out);

// strtod with from_chars's rules, in the C locale's format (the only one the course reads).
bool parseDecimalFallback(std::string_view text, double& out);
bool parseDecimalFallback(std::string_view text, float& out);

// The shortest text that parses back as exactly `v` (std::to_chars; without it, the fewest %g
// digits that read back the same).
std::string shortestDecimal(float v);
std::string shortestDecimalFallback(float v);

}  // namespace shadowlab

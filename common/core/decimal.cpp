#include "core/decimal.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace shadowlab {
namespace {

// from_chars's grammar, before strtod sees the text: an optional '-', then digits with at most one
// '.', at least one digit, then an optional exponent (e or E, an optional sign, digits). No hex, no
// inf or nan, no '+' in front, no spaces.
bool decimalSyntax(std::string_view t) {
  std::size_t i = 0;
  if (i < t.size() && t[i] == '-') ++i;
  std::size_t digits = 0;
  bool point = false;
  for (; i < t.size(); ++i) {
    if (t[i] >= '0' && t[i] <= '9') ++digits;
    else if (t[i] == '.' && !point) point = true;
    else break;
  }
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    if (i == start) return false;
  }
  return i == t.size();
}

template <class T>
bool viaFromChars(std::string_view text, T& out) {
#if defined(__cpp_lib_to_chars)
  const char* end = text.data() + text.size();
  T value{};
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return false;
  out = value;
  return true;
#else
  return parseDecimalFallback(text, out);
#endif
}

}  // namespace

namespace {
template <class T>
bool fallback(std::string_view text, T& out, T (*strto)(const char*, char**)) {
  if (!decimalSyntax(text)) return false;
  const std::string copy(text);
  errno = 0;
  char* end = nullptr;
  const T value = strto(copy.c_str(), &end);
  // ERANGE: past the type's range either way, which from_chars refuses too
  if (end != copy.c_str() + copy.size() || errno == ERANGE || !std::isfinite(value)) return false;
  out = value;
  return true;
}
}  // namespace

bool parseDecimalFallback(std::string_view text, double& out) { return fallback<double>(text, out, std::strtod); }
bool parseDecimalFallback(std::string_view text, float& out) { return fallback<float>(text, out, std::strtof); }

bool parseDecimal(std::string_view text, float& out) { return viaFromChars(text, out); }
bool parseDecimal(std::string_view text, double& out) { return viaFromChars(text, out); }

std::string shortestDecimalFallback(float v) {
  char buf[48];
  for (int digits = 1; digits <= 9; ++digits) {  // 9 significant digits hold every float exactly
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) == v) break;
  }
  return buf;
}

std::string shortestDecimal(float v) {
#if defined(__cpp_lib_to_chars)
  char buf[48];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
#else
  return shortestDecimalFallback(v);
#endif
}

}  // namespace shadowlab

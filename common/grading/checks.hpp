#pragma once
// Checks for graded cases that say what went wrong. A failing CHECK_NEAR prints, in a few lines,
// the call, the expected and the actual value (glm vectors and matrices as numbers) and the
// tolerance; CAPTURE(x) / INFO(...) add the case's inputs, printed the same way:
//
//   tests/grading/ex01_tests.cpp:31: ex01::lightContribution(N, L, V, I, 1, 1, kd, ks, 10)
//     expected  (1, 1, 1)
//     actual    (0, 0, 0)
//     tolerance 0.0001 per component (worst difference 1)
//     N := (0, 0, 1)
//
// In a loop over random cases, stop at the first failure (CHECK_NEAR returns false) so one wrong
// formula prints one case, not two hundred.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include <glm/glm.hpp>

namespace shadowlab::grading {

std::string show(double v);
inline std::string show(float v) { return show(double(v)); }
inline std::string show(int v) { return std::to_string(v); }
inline std::string show(long long v) { return std::to_string(v); }
inline std::string show(bool v) { return v ? "true" : "false"; }

template <glm::length_t L, class T, glm::qualifier Q>
std::string show(const glm::vec<L, T, Q>& v) {
  std::string s = "(";
  for (glm::length_t i = 0; i < L; ++i) s += (i ? ", " : "") + show(v[i]);
  return s + ")";
}

// Rows as the maths reads them (GLM stores columns: m[column][row]).
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
std::string show(const glm::mat<C, R, T, Q>& m) {
  std::string s = "rows [";
  for (glm::length_t r = 0; r < R; ++r) {
    s += r ? " | " : "";
    for (glm::length_t c = 0; c < C; ++c) s += (c ? " " : "") + show(m[c][r]);
  }
  return s + "]";
}

struct Tolerance {
  double value = 0;
  bool relative = false;  // value times max(1, the largest |component| of the expected value)
};
inline Tolerance relativeTolerance(double v) { return {v, true}; }
// 1e-5 relative: no looser than doctest's default Approx (1.2e-5 (1 + |value|)).
inline constexpr Tolerance kApprox{1e-5, true};

// The largest absolute difference over all components; infinite when either holds a NaN.
inline double difference(double a, double e) {
  if (std::isnan(a) || std::isnan(e)) return std::numeric_limits<double>::infinity();
  if (a == e) return 0;  // equal infinities
  return std::abs(a - e);
}
inline double largest(double e) { return std::abs(e); }
template <glm::length_t L, class T, glm::qualifier Q>
double difference(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& e) {
  double d = 0;
  for (glm::length_t i = 0; i < L; ++i) d = std::max(d, difference(double(a[i]), double(e[i])));
  return d;
}
template <glm::length_t L, class T, glm::qualifier Q>
double largest(const glm::vec<L, T, Q>& e) {
  double d = 0;
  for (glm::length_t i = 0; i < L; ++i) d = std::max(d, std::abs(double(e[i])));
  return d;
}
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
double difference(const glm::mat<C, R, T, Q>& a, const glm::mat<C, R, T, Q>& e) {
  double d = 0;
  for (glm::length_t c = 0; c < C; ++c) d = std::max(d, difference(a[c], e[c]));
  return d;
}
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
double largest(const glm::mat<C, R, T, Q>& e) {
  double d = 0;
  for (glm::length_t c = 0; c < C; ++c) d = std::max(d, largest(e[c]));
  return d;
}

// Reports a failed comparison to doctest (and so to the case's result); returns `ok`.
bool report(bool ok, const char* file, int line, const std::string& what, const std::string& expected,
            const std::string& actual, const std::string& tolerance);
std::string describeTolerance(const Tolerance& t, double tolerance, double worst, bool scalar);

template <class A, class E>
bool checkNear(const char* file, int line, const char* what, const A& actual, const E& expected, Tolerance tol) {
  const A e = A(expected);
  const double worst = difference(actual, e);
  const double allowed = tol.relative ? tol.value * std::max(1.0, largest(e)) : tol.value;
  constexpr bool scalar = std::is_arithmetic_v<A>;
  return report(worst <= allowed, file, line, what, show(e), show(actual),
                describeTolerance(tol, allowed, worst, scalar));
}
template <class A, class E>
bool checkNear(const char* file, int line, const char* what, const A& actual, const E& expected, double tol) {
  return checkNear(file, line, what, actual, expected, Tolerance{tol, false});
}

template <class T>
auto shownValue(const T& v) {
  if constexpr (std::is_enum_v<T>) return show(int(v));
  else return show(v);
}
template <class A, class E>
bool checkExact(const char* file, int line, const char* what, const A& actual, const E& expected) {
  const A e = A(expected);
  return report(actual == e, file, line, what, shownValue(e), shownValue(actual), "exact");
}

inline bool checkTrue(const char* file, int line, const char* what, bool condition) {
  return report(condition, file, line, what, "true", "false", "exact");
}

}  // namespace shadowlab::grading

// glm values in CAPTURE / INFO and in doctest's own CHECK(a == b) output, as numbers.
namespace doctest {
template <glm::length_t L, class T, glm::qualifier Q>
struct StringMaker<glm::vec<L, T, Q>> {
  static String convert(const glm::vec<L, T, Q>& v) { return shadowlab::grading::show(v).c_str(); }
};
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
struct StringMaker<glm::mat<C, R, T, Q>> {
  static String convert(const glm::mat<C, R, T, Q>& m) { return shadowlab::grading::show(m).c_str(); }
};
}  // namespace doctest

// CHECK_NEAR(actual, expected, tolerance): tolerance is absolute per component (a number) or
// shadowlab::grading::relativeTolerance(x). Returns whether it held.
#define CHECK_NEAR(actual, expected, tolerance) \
  ::shadowlab::grading::checkNear(__FILE__, __LINE__, #actual, (actual), (expected), (tolerance))
// CHECK_TRUE(condition): a property; say what was compared with INFO. Returns whether it held.
#define CHECK_TRUE(condition) ::shadowlab::grading::checkTrue(__FILE__, __LINE__, #condition, (condition))
// CHECK_EXACT(actual, expected): integers, booleans, enums.
#define CHECK_EXACT(actual, expected) \
  ::shadowlab::grading::checkExact(__FILE__, __LINE__, #actual, (actual), (expected))

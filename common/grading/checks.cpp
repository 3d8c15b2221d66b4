#include "grading/checks.hpp"

#include <cstdio>

namespace shadowlab::grading {

std::string show(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", v == 0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string describeTolerance(const Tolerance& t, double allowed, double worst, bool scalar) {
  std::string s = show(allowed);
  if (t.relative) s += " (" + show(t.value) + " relative)";
  if (!scalar) s += " per component";
  return s + ", difference " + show(worst);
}

bool report(bool ok, const char* file, int line, const std::string& what, const std::string& expected,
            const std::string& actual, const std::string& tolerance) {
  if (ok) {
    DOCTEST_CHECK(ok);  // counted as a passing assertion
    return true;
  }
  DOCTEST_ADD_FAIL_CHECK_AT(
      file, line, what << "\n  expected  " << expected << "\n  actual    " << actual << "\n  tolerance " << tolerance);
  return false;
}

}  // namespace shadowlab::grading

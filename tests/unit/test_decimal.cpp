#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/decimal.hpp"

using namespace shadowlab;

// The browser build parses numbers with parseDecimalFallback (its libc++ has no floating-point
// from_chars); natively parseDecimal is from_chars. The same text must get the same answer.
namespace {
const std::vector<std::string> kTexts = {"0",
                                         "1",
                                         "-1",
                                         "1.5",
                                         "-2e-3",
                                         ".5",
                                         "5.",
                                         "1e10",
                                         "1E+3",
                                         "0.000001",
                                         "123456789012345678901234567890",
                                         "3.4028234e38",
                                         "3.5e38",
                                         "1e39",
                                         "1e308",
                                         "1e309",
                                         "1e-30",
                                         "1e-50",
                                         "1e-400",
                                         "-0",
                                         "00012",
                                         "0.1",
                                         "",
                                         "+1",
                                         " 1",
                                         "1 ",
                                         "1x",
                                         "0x10",
                                         "nan",
                                         "inf",
                                         "-inf",
                                         "infinity",
                                         "1e",
                                         "1e+",
                                         ".",
                                         "-",
                                         "-.",
                                         "1..2",
                                         "1.2.3",
                                         "e5",
                                         "1,5",
                                         "1e5.5",
                                         "--1",
                                         "0b1",
                                         "\t2"};

template <class T>
void sameAnswers() {
  for (const std::string& text : kTexts) {
    CAPTURE(text);
    T a = T(-7), b = T(-7);
    const bool fromChars = parseDecimal(text, a), fallback = parseDecimalFallback(text, b);
    CHECK(fromChars == fallback);
    if (fromChars && fallback) CHECK(a == b);
  }
}
}  // namespace

TEST_CASE("decimal: the fallback accepts exactly what from_chars accepts, with the same value") {
  sameAnswers<float>();
  sameAnswers<double>();
}

TEST_CASE("decimal: a finite decimal number and nothing else") {
  for (const char* good : {"1.5", "-2e-3", ".5", "7", "1e10"}) {
    double d = 0;
    CHECK_MESSAGE(parseDecimalFallback(good, d), good);
  }
  for (const char* bad : {"", "+1", " 1", "1x", "0x10", "nan", "inf", "1e", "1e999"}) {
    double d = 42;
    CHECK_MESSAGE(!parseDecimalFallback(bad, d), bad);
    CHECK(d == 42);  // a refused text leaves the value alone
  }
  float f = 0;
  CHECK(!parseDecimalFallback("1e39", f));  // past float's range, within double's
  CHECK(parseDecimalFallback("0.1", f));
  CHECK(f == 0.1f);
}

TEST_CASE("decimal: the shortest text reads back as the same float, in the browser's fallback too") {
  for (float v : {0.0f, 1.0f, -1.0f, 0.1f, 1.0f / 3.0f, 3.14159265f, 1e-7f, 12345.678f, 3.4028234e38f, -2.5e-20f, 0.75f,
                  100.0f}) {
    CAPTURE(v);
    for (const std::string& text : {shortestDecimal(v), shortestDecimalFallback(v)}) {
      float back = -1;
      CHECK(parseDecimalFallback(text, back));
      CHECK(back == v);
    }
    CHECK(shortestDecimalFallback(v).size() <= shortestDecimal(v).size() + 4);  // %g may add an exponent's "+0"
  }
  CHECK(shortestDecimalFallback(0.1f) == "0.1");
  CHECK(shortestDecimalFallback(0.75f) == "0.75");
}

#include <doctest/doctest.h>
#include "test_support.hpp"
TEST_CASE("support: the seed is stable within a run") {
  CHECK(shadowlab::test::seed() == shadowlab::test::seed());
  CHECK(shadowlab::test::seedFor("a") != shadowlab::test::seedFor("b"));
}

// Cases whose names hold the characters test registration must keep: ';' (CMake's list
// separator, which doctest's own discovery split on) and ',' (doctest's filter separator).
// tests/registration.cmake proves each becomes one ctest entry that runs exactly one case.
#include <doctest/doctest.h>

TEST_CASE("registration fixture: a name with a semicolon; kept whole") { CHECK(1 + 1 == 2); }
TEST_CASE("registration fixture: a name with a comma, kept whole") { CHECK(2 * 2 == 4); }
TEST_CASE("registration fixture: a plain name") { CHECK(3 - 1 == 2); }

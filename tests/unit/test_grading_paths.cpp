// grading/cases: the file names reports give a case (JUnit class names, failure lines), relative to
// the tree whichever way the compiler was given the file.
#include <doctest/doctest.h>

#include "grading/cases.hpp"
#include "test_support.hpp"

using shadowlab::grading::repositoryRelative;

TEST_CASE("grading: reports name files relative to the source tree") {
  const std::string root = shadowlab::test::sourceTree();
  CHECK(repositoryRelative(root + "/tests/grading/ex01_tests.cpp") == "tests/grading/ex01_tests.cpp");
  // Through ccache __FILE__ is relative to the build folder (build/default inside the tree).
  CHECK(repositoryRelative("../../tests/grading/ex01_tests.cpp") == "tests/grading/ex01_tests.cpp");
  CHECK(repositoryRelative("./tests/unit/a.cpp") == "tests/unit/a.cpp");
  CHECK(repositoryRelative("tests/unit/a.cpp") == "tests/unit/a.cpp");
  // Outside the tree: unchanged, and a name merely starting like the root is not under it.
  CHECK(repositoryRelative("/usr/include/doctest/doctest.h") == "/usr/include/doctest/doctest.h");
  CHECK(repositoryRelative(root + "-other/x.cpp") == root + "-other/x.cpp");
  CHECK(repositoryRelative("") == "");
}

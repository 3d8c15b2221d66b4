// grading/cases: the file names reports give a case (JUnit class names, failure lines), relative to
// the tree whichever way the compiler was given the file; grading/report: which renders can grade.
#include <doctest/doctest.h>

#include "grading/cases.hpp"
#include "grading/report.hpp"
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

// A hidden render whose random placement shows nothing to grade is drawn again (glsl_grader): the
// reference run of lesson 09 at seed 20 (camera.yaw facing a wall at arm's length, one pixel facing
// the light, none in shadow) let the untouched stub of exercise 09.6 pass a hidden render.
TEST_CASE("grading: a hidden render is graded only where the reference shows shadow to tell apart") {
  using shadowlab::grading::renderInformative;
  std::string why;
  const auto hard = [](int facing, int shadowed) {
    return nlohmann::json{
        {"width", 320}, {"height", 180}, {"hard", {{"facing_pixels", facing}, {"reference_shadowed", shadowed}}}};
  };
  CHECK_FALSE(renderInformative(hard(1, 0), why));               // seed 20's view
  CHECK(why.rfind("0% of the view in shadow, 0.0017", 0) == 0);  // 1 pixel of 57600 lit
  CHECK(renderInformative(hard(57487, 6000), why));              // lesson 09's usual view: a tenth in shadow
  CHECK(renderInformative(hard(10000, 3000), why));              // a sixth of the view faces the light
  CHECK_FALSE(renderInformative(hard(57487, 500), why));         // "lit" everywhere would pass
  CHECK_FALSE(renderInformative(hard(57487, 57000), why));       // "shadowed" everywhere would
  CHECK(renderInformative(hard(2304, 1152), why));               // 2% of 320 x 180 each, exactly
  CHECK_FALSE(renderInformative(hard(2303, 1152), why));
  CHECK_FALSE(renderInformative(hard(2303, 1151), why));
  const auto soft = [](int seen, int umbra) {
    return nlohmann::json{{"width", 320}, {"height", 180}, {"soft", {{"pixels", seen}, {"umbra_pixels", umbra}}}};
  };
  CHECK(renderInformative(soft(50000, 2000), why));
  CHECK_FALSE(renderInformative(soft(50000, 100), why));  // under 0.5% umbra
  CHECK(renderInformative(soft(50000, 288), why));        // 0.5% of 320 x 180
  CHECK_FALSE(renderInformative(soft(2500, 2000), why));  // umbra nearly all that is seen
  CHECK_FALSE(renderInformative(nlohmann::json{{"width", 320}, {"height", 180}}, why));
  CHECK_FALSE(renderInformative(nlohmann::json::parse("not json", nullptr, false), why));
  CHECK(why == "no ground-truth figures");
}

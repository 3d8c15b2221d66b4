// The configure-time paths of test_support.hpp: the one test file compiled with them.
#include "test_support.hpp"

#if !defined(SHADOWLAB_SOURCE_ROOT) || !defined(SHADOWLAB_TEST_DATA)
#error "SHADOWLAB_SOURCE_ROOT and SHADOWLAB_TEST_DATA must be defined for this file (tests/CMakeLists.txt)"
#endif

namespace shadowlab::test {

std::string sourceTree() { return SHADOWLAB_SOURCE_ROOT; }
std::string testData() { return SHADOWLAB_TEST_DATA; }

}  // namespace shadowlab::test

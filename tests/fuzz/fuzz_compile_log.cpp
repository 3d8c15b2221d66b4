// Compile-log mapping (core/shader_source, used by gl/program.cpp on every driver log): any log
// maps, line for line, whatever its line lengths.
#include <algorithm>

#include "core/shader_source.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string log = fuzz::text(data, size);
  const std::string mapped = mapCompileLog(log, {"/s/top.frag", "/s/lib/light.glsl", "/s/common/shadow.glsl"});
  FUZZ_CHECK(std::count(mapped.begin(), mapped.end(), '\n') == std::count(log.begin(), log.end(), '\n'));
  FUZZ_CHECK(mapCompileLog(log, {}) == log);  // no files: nothing to map
  return 0;
}

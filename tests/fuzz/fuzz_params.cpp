// --set NAME=VALUE (core/params): one line an assignment, applied alone and then all as one
// change; each is taken or refused with ParamError, and a refusal changes nothing.
#include "fuzz_support.hpp"
#include "fuzz_registry.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Registry r;
  const std::vector<std::string> lines = fuzz::split(fuzz::text(data, size), '\n', 64);
  for (const std::string& line : lines) {
    const auto before = r.values();
    try {
      r.reg.assign(line);
    } catch (const ParamError&) { FUZZ_CHECK(r.values() == before); }
    r.checkConsistent();
  }
  const auto before = r.values();
  try {
    r.reg.assignAll(lines);
  } catch (const ParamError&) { FUZZ_CHECK(r.values() == before); }
  r.checkConsistent();
  return 0;
}

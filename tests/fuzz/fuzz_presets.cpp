// Preset files (core/params): load, validate and apply every preset, or ParamError; a refused
// preset leaves the registry as it was.
#include <sstream>

#include "fuzz_support.hpp"
#include "fuzz_registry.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Registry r;
  std::istringstream in(fuzz::text(data, size));
  try {
    const PresetFile file = PresetFile::read(in, "fuzz.txt");
    bool valid = true;
    try {
      file.validate(r.reg);
    } catch (const ParamError&) { valid = false; }
    for (const std::string& name : file.names()) {
      const auto before = r.values();
      try {
        file.apply(name, r.reg);
      } catch (const ParamError&) {
        FUZZ_CHECK(!valid);                // validate() passed every preset
        FUZZ_CHECK(r.values() == before);  // and a refused one changes nothing
      }
      r.checkConsistent();
    }
  } catch (const ParamError&) {}
  return 0;
}

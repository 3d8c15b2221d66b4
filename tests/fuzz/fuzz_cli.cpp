// The command line (core/cli): one argument a line; a CommandLine within its documented bounds,
// or CliError.
#include "core/cli.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = fuzz::split(fuzz::text(data, size), '\n', 256);
  args.insert(args.begin(), "lesson");
  try {
    const CommandLine cl = parseCommandLine(args);
    FUZZ_CHECK(cl.width >= 16 && cl.width <= kMaxFramebufferSide);
    FUZZ_CHECK(cl.height >= 16 && cl.height <= kMaxFramebufferSide);
    FUZZ_CHECK(cl.frames == -1 || cl.frames >= 1);
    FUZZ_CHECK(cl.uiScale == 0 || (cl.uiScale >= 0.5f && cl.uiScale <= 4.0f));
    for (const std::string& s : cl.sets) FUZZ_CHECK(s.find('=') != std::string::npos);
  } catch (const CliError&) {}
  return 0;
}

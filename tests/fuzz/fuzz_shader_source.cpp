// The shader #include preprocessor (core/shader_source): the input is up to 128 files separated
// by NUL bytes, written to a scratch folder as top.frag, f1.glsl, f2.glsl, ... (they include each
// other by those names); the expansion, or ShaderSourceError.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/shader_source.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {
// In memory where there is a tmpfs: on a disk the file system calls cost 16 ms an input.
const fs::path& scratch() {
  static const fs::path dir = [] {
    std::error_code ec;
    const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
    const fs::path d = base / ("shadowlab_fuzz_shader_" + std::to_string(getpid()));
    fs::create_directories(d / "inc");
    return d;
  }();
  return dir;
}

fs::path fileName(std::size_t i) {
  const fs::path& dir = scratch();
  return i == 0 ? dir / "top.frag" : (i % 2 ? dir : dir / "inc") / ("f" + std::to_string(i) + ".glsl");
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Includes stay in the scratch folder: an absolute path or '..' could name any file of the
  // machine (/proc/kcore reads as a 128 TB regular file). Those paths are resolved by the same code.
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  if (input.find("\"/") != std::string_view::npos || input.find("..") != std::string_view::npos) return 0;
  static std::size_t written = 0;  // files of the previous input: those past this one's count go
  const std::vector<std::string> files = fuzz::split(fuzz::text(data, size), '\0', 128);
  const fs::path& dir = scratch();
  for (std::size_t i = 0; i < files.size(); ++i) std::ofstream(fileName(i), std::ios::binary) << files[i];
  for (std::size_t i = files.size(); i < written; ++i) fs::remove(fileName(i));
  written = files.size();
  try {
    const ShaderSource s = loadShaderSource((dir / "top.frag").string(), {(dir / "inc").string()});
    FUZZ_CHECK(!s.files.empty() && s.files.size() == s.dependencies.size());
    FUZZ_CHECK(s.files.size() <= kMaxIncludeDepth * files.size());
  } catch (const ShaderSourceError&) {}
  return 0;
}

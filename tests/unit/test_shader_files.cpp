// core/shader_files: shader text that is not on disk, found by the #include preprocessor (GLSL a
// program generates, and the files sealed into the program for the student handout).
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/paths.hpp"
#include "core/shader_files.hpp"
#include "core/shader_source.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("shadowlab_shader_files_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return fs::canonical(p);
}
void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}
std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("shader files: registered text is found as an include and as a top-level file, and never reloads") {
  const fs::path root = scratch("registered");
  registerShaderText("generated/helper.glsl", "float helper() { return 2.0; }\n");
  registerShaderText("generated/top.frag", "#version 410 core\n#include \"generated/helper.glsl\"\nvoid main() {}\n");
  const ShaderSource s = loadShaderSource((root / "generated/top.frag").string(), {root.string()});
  CHECK(s.text.find("float helper() { return 2.0; }") != std::string::npos);
  REQUIRE(s.files.size() == 2);
  CHECK(s.files[1] == (root / "generated/helper.glsl").string());
  for (const FileStamp& d : s.dependencies) CHECK_FALSE(d.onDisk);
  CHECK_FALSE(dependenciesChanged(s));  // virtual text does not change under the program
  fs::remove_all(root);
}

TEST_CASE("shader files: a real file wins over registered text of the same name") {
  const fs::path root = scratch("disk_wins");
  registerShaderText("a/shared.glsl", "float fromRegistry;\n");
  write(root / "a/shared.glsl", "float fromDisk;\n");
  write(root / "a/top.frag", "#version 410 core\n#include \"shared.glsl\"\nvoid main() {}\n");
  const ShaderSource s = loadShaderSource((root / "a/top.frag").string(), {root.string()});
  CHECK(s.text.find("fromDisk") != std::string::npos);
  CHECK(s.text.find("fromRegistry") == std::string::npos);
  CHECK(s.dependencies.back().onDisk);
  fs::remove_all(root);
}

TEST_CASE("shader files: a missing include that is nowhere virtual still names what was searched") {
  const fs::path root = scratch("missing");
  write(root / "top.frag", "#version 410 core\n#include \"nowhere/none.glsl\"\nvoid main() {}\n");
  CHECK_THROWS_WITH_AS(loadShaderSource((root / "top.frag").string(), {root.string()}),
                       doctest::Contains("cannot find include \"nowhere/none.glsl\""), ShaderSourceError);
  fs::remove_all(root);
}

TEST_CASE("shader files: every file the handout seals is in the program, byte for byte the file on disk") {
  std::ifstream manifest(sourceRoot() + "/tools/handout/sealed_shaders.txt");
  REQUIRE(manifest);
  int sealed = 0;
  for (std::string line; std::getline(manifest, line);) {
    line = line.substr(0, line.find('#'));
    line.erase(line.find_last_not_of(" \t") + 1);
    if (line.empty()) continue;
    INFO("sealed file ", line);
    const std::optional<std::string> text = virtualShaderText(line);
    REQUIRE(text.has_value());
    CHECK(text->size() > 100);
    const fs::path onDisk = shaderRoot() + "/" + line;
    if (fs::exists(onDisk)) CHECK(*text == read(onDisk));  // the instructor's tree; the handout has no copy
    ++sealed;
  }
  CHECK(sealed >= 3);
}

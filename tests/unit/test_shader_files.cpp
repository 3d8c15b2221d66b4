// core/shader_files: shader text that is not on disk, found by the #include preprocessor (GLSL a
// program generates, and the files sealed into the program for the student handout).
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
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
  int sealed = 0, withheld = 0;
  for (std::string line; std::getline(manifest, line);) {
    line = line.substr(0, line.find('#'));
    line.erase(line.find_last_not_of(" \t") + 1);
    if (line.empty()) continue;
    if (line.rfind("withheld ", 0) == 0) {  // an answer: its name only, never its text
      line = line.substr(line.find_first_not_of(' ', 9));
      INFO("withheld file ", line);
      CHECK(shaderWithheld(line));
      CHECK_FALSE(virtualShaderText(line).has_value());
      ++withheld;
      continue;
    }
    INFO("sealed file ", line);
    CHECK_FALSE(shaderWithheld(line));
    const std::optional<std::string> text = virtualShaderText(line);
    REQUIRE(text.has_value());
    CHECK(text->size() > 100);
    const fs::path onDisk = shaderRoot() + "/" + line;
    if (fs::exists(onDisk)) CHECK(*text == read(onDisk));  // the instructor's tree; the handout has no copy
    ++sealed;
  }
  CHECK(sealed >= 3);
  CHECK(withheld >= 9);  // every lesson's GLSL exercise, 02 to 10
}

// The student handout: the reference GLSL of an exercise is absent; the student's exercises.glsl
// stands in, in both branches of the shaders' `#ifdef STUDENT ... #else ... #endif`, and the
// preprocessor notes it. A file that is not withheld still fails to resolve.
TEST_CASE("shader files: a withheld answer, absent, is the student's exercises.glsl beside it, and noted") {
  const fs::path root = scratch("withheld");
  const std::string lesson = "03_shadow_quality";
  REQUIRE(shaderWithheld(lesson + "/exercises_reference.glsl"));
  CHECK(withheldStandIn(lesson + "/exercises_reference.glsl") == lesson + "/exercises.glsl");
  write(root / lesson / "exercises.glsl", "float pcfKernel() { return 0.25; } // the student's\n");
  write(root / lesson / "top.frag", "#version 410 core\n#ifdef STUDENT\n#include \"" + lesson +
                                        "/exercises.glsl\"\n#else\n#include \"" + lesson +
                                        "/exercises_reference.glsl\"\n#endif\nvoid main() {}\n");
  const ShaderSource s = loadShaderSource((root / lesson / "top.frag").string(), {root.string()});
  std::size_t copies = 0;
  for (auto at = s.text.find("the student's"); at != std::string::npos; at = s.text.find("the student's", at + 1))
    ++copies;
  CHECK(copies == 2);  // the #ifdef branch and the #else branch
  for (std::size_t i = 1; i < s.files.size(); ++i) CHECK(s.files[i] == (root / lesson / "exercises.glsl").string());
  const std::vector<std::string> replaced = withheldReplaced();
  CHECK(std::find(replaced.begin(), replaced.end(), lesson + "/exercises_reference.glsl") != replaced.end());

  write(root / "other.frag", "#version 410 core\n#include \"" + lesson + "/answers.glsl\"\nvoid main() {}\n");
  CHECK_THROWS_WITH_AS(loadShaderSource((root / "other.frag").string(), {root.string()}),
                       doctest::Contains("cannot find include"), ShaderSourceError);
  fs::remove_all(root);
}

// core/shader_source and core/paths: the #include preprocessor, its #line bookkeeping, compile-log
// mapping, stage detection and the data roots. Expected texts are written out by hand from the
// GLSL 4.10 rule that `#line N S` makes the NEXT line number N of source string S.
#include <doctest/doctest.h>

#include "core/paths.hpp"
#include "core/shader_source.hpp"
#include "test_support.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

// A scratch directory per test case, removed afterwards; the pid keeps parallel ctest processes
// (one per case) apart.
class TempDir {
 public:
  TempDir() {
    static int serial = 0;
    path_ = fs::temp_directory_path() /
            ("shadowlab_shader_source_" + std::to_string(getpid()) + "_" + std::to_string(serial++));
    fs::remove_all(path_);
    fs::create_directories(path_);
    path_ = fs::canonical(path_);  // loadShaderSource reports canonical paths
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string write(const std::string& relative, const std::string& text) const {
    const fs::path file = path_ / relative;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }
  std::string operator/(const std::string& relative) const { return (path_ / relative).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Sets (or unsets, with nullopt) an environment variable for one scope and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value->c_str(), 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::string errorOf(const std::string& path, const std::vector<std::string>& includeDirs = {}) {
  try {
    loadShaderSource(path, includeDirs);
  } catch (const ShaderSourceError& e) { return e.what(); }
  return "<no error>";
}

std::vector<std::string> readLines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// An independent model of how a GLSL 4.10 compiler numbers the expanded text: checks that every
// line that is not a #line directive (or the hoisted #version) is exactly the line of the original
// file that the compiler would attribute it to. This is what makes compile logs point at the right
// place, for any include structure.
void checkLineAttribution(const ShaderSource& source) {
  std::istringstream text(source.text);
  std::string line;
  std::size_t sourceIndex = 0, lineNumber = 1;
  std::map<std::size_t, std::vector<std::string>> originals;
  bool first = true;
  while (std::getline(text, line)) {
    if (first && line.rfind("#version", 0) == 0) {  // hoisted; checked by the exact-text tests
      first = false;
      ++lineNumber;
      continue;
    }
    first = false;
    if (line.rfind("#line ", 0) == 0) {
      std::istringstream directive(line.substr(6));
      directive >> lineNumber >> sourceIndex;
      continue;
    }
    REQUIRE(sourceIndex < source.files.size());
    auto& lines = originals[sourceIndex];
    if (lines.empty()) lines = readLines(source.files[sourceIndex]);
    INFO("source ", sourceIndex, " (", source.files[sourceIndex], ") line ", lineNumber);
    REQUIRE(lineNumber >= 1);
    REQUIRE(lineNumber <= lines.size());
    const std::string& original = lines[lineNumber - 1];
    // Replaced directives (#include, repeated includes, the hoisted #version) become blank lines.
    if (line.empty() && original.find('#') != std::string::npos) {
      ++lineNumber;
      continue;
    }
    CHECK(line == original);
    ++lineNumber;
  }
}

}  // namespace

TEST_CASE("shader source: nested includes expand with #line directives at every boundary") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "#version 410 core\n"
                                    "#include \"a.glsl\"\n"
                                    "void main() {}\n");
  dir.write("a.glsl",
            "// a\n"
            "#include \"sub/b.glsl\"\n"
            "float a() { return b(); }\n");
  dir.write("sub/b.glsl", "float b() { return 1.0; }\n");

  const ShaderSource source = loadShaderSource(top, {});
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 2 0\n"
        "#line 1 1\n"
        "// a\n"
        "#line 1 2\n"
        "float b() { return 1.0; }\n"
        "#line 3 1\n"
        "float a() { return b(); }\n"
        "#line 3 0\n"
        "void main() {}\n");
  REQUIRE(source.files.size() == 3);
  CHECK(source.files[0] == top);
  CHECK(source.files[1] == dir / "a.glsl");
  CHECK(source.files[2] == dir / "sub/b.glsl");
  REQUIRE(source.dependencies.size() == 3);
  CHECK(source.dependencies[0].path == top);
  CHECK(source.dependencies[1].path == dir / "a.glsl");
  CHECK(source.dependencies[2].path == dir / "sub/b.glsl");
  checkLineAttribution(source);
}

TEST_CASE("shader source: a file included twice is expanded once, whatever the spelling") {
  TempDir dir;
  const std::string top = dir.write("lib/top.vert",
                                    "#version 410 core\n"
                                    "#include \"common.glsl\"\n"
                                    "#include \"../lib/./common.glsl\"\n"
                                    "#include \"other.glsl\"\n"
                                    "void main() {}\n");
  dir.write("lib/common.glsl", "const float k = 1.0;\n");
  dir.write("lib/other.glsl",
            "#include \"common.glsl\"\n"
            "float other() { return k; }\n");

  const ShaderSource source = loadShaderSource(top, {});
  // The repeats become blank lines, so the numbering continues without an extra #line.
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 2 0\n"
        "#line 1 1\n"
        "const float k = 1.0;\n"
        "#line 3 0\n"
        "\n"
        "#line 1 2\n"
        "\n"
        "float other() { return k; }\n"
        "#line 5 0\n"
        "void main() {}\n");
  REQUIRE(source.files.size() == 3);
  CHECK(source.files[1] == dir / "lib/common.glsl");
  CHECK(source.files[2] == dir / "lib/other.glsl");
  CHECK(source.dependencies.size() == 3);
  checkLineAttribution(source);
}

TEST_CASE("shader source: includes resolve next to the includer first, then in the include dirs in order") {
  TempDir dir;
  const std::string top = dir.write("src/top.frag",
                                    "#version 410 core\n"
                                    "#include \"near.glsl\"\n"
                                    "#include \"far.glsl\"\n");
  dir.write("src/near.glsl", "// near: local copy\n");
  dir.write("inc1/near.glsl", "// near: include-dir copy\n");
  dir.write("inc1/far.glsl", "// far: first include dir\n");
  dir.write("inc2/far.glsl", "// far: second include dir\n");

  const ShaderSource source = loadShaderSource(top, {dir / "inc1", dir / "inc2"});
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 2 0\n"
        "#line 1 1\n"
        "// near: local copy\n"
        "#line 3 0\n"
        "#line 1 2\n"
        "// far: first include dir\n"
        "#line 4 0\n");
  REQUIRE(source.files.size() == 3);
  CHECK(source.files[1] == dir / "src/near.glsl");
  CHECK(source.files[2] == dir / "inc1/far.glsl");

  // Without the first include dir the second one is searched.
  const ShaderSource fallback = loadShaderSource(top, {dir / "inc2"});
  REQUIRE(fallback.files.size() == 3);
  CHECK(fallback.files[2] == dir / "inc2/far.glsl");
}

TEST_CASE("shader source: #version is emitted first even after leading comments") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "// header comment\n"
                                    "/* #version 100 in a comment is not the version */\n"
                                    "#version 410 core\n"
                                    "void main() {}\n");
  const ShaderSource source = loadShaderSource(top, {});
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 1 0\n"
        "// header comment\n"
        "/* #version 100 in a comment is not the version */\n"
        "\n"
        "void main() {}\n");
  checkLineAttribution(source);
}

// The text gl::Program compiles and shader_check --variants validates: one function for both.
TEST_CASE("shader source: withDefines puts the defines after #version and keeps the file's numbering") {
  TempDir dir;
  const std::string top = dir.write("top.frag", "#version 410 core\nvoid main() {}\n");
  const ShaderSource source = loadShaderSource(top, {});
  CHECK(withDefines(source.text, {}) == source.text);
  CHECK(withDefines(source.text, {"PCSS", "SEARCH_TAPS 16"}) ==
        "#version 410 core\n"
        "#define PCSS\n"
        "#define SEARCH_TAPS 16\n"
        "#line 2 0\n"
        "void main() {}\n");
  // A text whose #version is not followed by the preprocessor's #line gets one.
  CHECK(withDefines("#version 410 core\nvoid main() {}\n", {"A 1"}) ==
        "#version 410 core\n#define A 1\n#line 2 0\nvoid main() {}\n");
}

TEST_CASE("shader source: a file without #version is passed through with its own numbering") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "void main() {}\n"
                                    "#include \"a.glsl\"\n");
  dir.write("a.glsl", "// a");  // no final newline: the output still ends lines with '\n'
  const ShaderSource source = loadShaderSource(top, {});
  CHECK(source.text ==
        "void main() {}\n"
        "#line 1 1\n"
        "// a\n"
        "#line 3 0\n");
}

TEST_CASE("shader source: CRLF files keep their line numbers and directives") {
  TempDir dir;
  const std::string top = dir.write("top.frag", "#version 410 core\r\n#include \"a.glsl\"\r\nvoid main() {}\r\n");
  dir.write("a.glsl", "float a;\r\n");
  const ShaderSource source = loadShaderSource(top, {});
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 2 0\n"
        "#line 1 1\n"
        "float a;\n"
        "#line 3 0\n"
        "void main() {}\n");
}

TEST_CASE("shader source: commented-out includes are left alone") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "#version 410 core\n"
                                    "// #include \"missing.glsl\"\n"
                                    "/*\n"
                                    "#include \"missing.glsl\"\n"
                                    "*/\n"
                                    "  #  include \"a.glsl\" // spaced out, with a trailing comment\n");
  dir.write("a.glsl", "float a;\n");
  const ShaderSource source = loadShaderSource(top, {});
  CHECK(source.text ==
        "#version 410 core\n"
        "#line 2 0\n"
        "// #include \"missing.glsl\"\n"
        "/*\n"
        "#include \"missing.glsl\"\n"
        "*/\n"
        "#line 1 1\n"
        "float a;\n"
        "#line 7 0\n");
}

TEST_CASE("shader source: an include cycle is an error naming the chain") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "#version 410 core\n"
                                    "#include \"b.glsl\"\n");
  dir.write("b.glsl", "#include \"c.glsl\"\n");
  dir.write("c.glsl",
            "// c\n"
            "#include \"b.glsl\"\n");
  CHECK(errorOf(top) ==
        dir / "c.glsl" + ":2: #include cycle: " + dir / "b.glsl" + " -> " + dir / "c.glsl" + " -> " + dir / "b.glsl");

  // A file including itself, and an include back to the top file, are cycles too.
  const std::string self = dir.write("self.frag", "#include \"self.frag\"\n");
  CHECK(errorOf(self) == self + ":1: #include cycle: " + self + " -> " + self);
  const std::string back = dir.write("back.frag", "#include \"back.glsl\"\n");
  dir.write("back.glsl", "\n\n#include \"back.frag\"\n");
  CHECK(errorOf(back) ==
        dir / "back.glsl" + ":3: #include cycle: " + back + " -> " + dir / "back.glsl" + " -> " + back);
}

TEST_CASE("shader source: a missing include names the target, the including file and line, and where it looked") {
  TempDir dir;
  const std::string top = dir.write("top.frag",
                                    "#version 410 core\n"
                                    "#include \"a.glsl\"\n");
  dir.write("a.glsl",
            "// a\n"
            "\n"
            "#include \"nowhere/missing.glsl\"\n");
  CHECK(errorOf(top, {dir / "inc"}) == dir / "a.glsl" + ":3: cannot find include \"nowhere/missing.glsl\" (searched " +
                                           dir.path().string() + ", " + dir / "inc" + ")");
}

TEST_CASE("shader source: a missing top-level file is an error naming it") {
  TempDir dir;
  CHECK(errorOf(dir / "absent.frag") == "cannot open shader file '" + dir / "absent.frag" + "'");
  // A directory is not a shader either.
  CHECK(errorOf(dir.path().string()) == "cannot open shader file '" + dir.path().string() + "'");
}

TEST_CASE("shader source: malformed #include lines are errors naming file and line") {
  TempDir dir;
  dir.write("ok.glsl", "\n");
  for (const std::string bad : {"#include <ok.glsl>", "#include ok.glsl", "#include \"ok.glsl", "#include \"\"",
                                "#include", "#include \"ok.glsl\" trailing"}) {
    CAPTURE(bad);
    const std::string top = dir.write("top.frag", "#version 410 core\n\n" + bad + "\n");
    CHECK(errorOf(top) == top + ":3: malformed #include (expected #include \"file\"): " + bad);
  }
  // Not the include directive at all: passed through for the compiler to judge.
  const std::string other = dir.write("other.frag", "#includes \"ok.glsl\"\n");
  CHECK(loadShaderSource(other, {}).text == "#includes \"ok.glsl\"\n");
}

TEST_CASE("shader source: dependenciesChanged sees edits and deletions of any file read") {
  TempDir dir;
  const std::string top = dir.write("top.frag", "#version 410 core\n#include \"a.glsl\"\n");
  const std::string a = dir.write("a.glsl", "float a;\n");
  const ShaderSource source = loadShaderSource(top, {});
  CHECK_FALSE(dependenciesChanged(source));

  // Move the time explicitly rather than sleeping past the file system's timestamp resolution.
  const auto original = fs::last_write_time(a);
  fs::last_write_time(a, original + std::chrono::seconds(2));
  CHECK(dependenciesChanged(source));
  fs::last_write_time(a, original);
  CHECK_FALSE(dependenciesChanged(source));

  fs::remove(a);
  CHECK(dependenciesChanged(source));
  CHECK_FALSE(dependenciesChanged(ShaderSource{}));
}

TEST_CASE("shader source: the sample fixtures expand with correct numbering and include-once") {
  const std::string root = test::testData() + "/shaders";
  const ShaderSource frag = loadShaderSource(root + "/sample.frag", {});
  // sample_common.glsl is included directly and again by sample_shadow.glsl: expanded once.
  REQUIRE(frag.files.size() == 3);
  CHECK(frag.files[0] == fs::canonical(root + "/sample.frag").string());
  CHECK(frag.files[1] == fs::canonical(root + "/include/sample_common.glsl").string());
  CHECK(frag.files[2] == fs::canonical(root + "/include/sample_shadow.glsl").string());
  CHECK(frag.text.rfind("#version 410 core\n#line 2 0\n", 0) == 0);
  checkLineAttribution(frag);

  const ShaderSource vert = loadShaderSource(root + "/sample.vert", {});
  REQUIRE(vert.files.size() == 2);
  checkLineAttribution(vert);
}

TEST_CASE("shader source: compile logs map to path:line for Mesa, NVIDIA and AMD/glslang") {
  const std::vector<std::string> files{"/s/top.frag", "/s/lib/light.glsl"};
  // Mesa: source:line(column)
  CHECK(mapCompileLog("0:12(5): error: `foo' undeclared\n", files) == "/s/top.frag:12: error: `foo' undeclared\n");
  CHECK(mapCompileLog("1:3(10): warning: unused variable", files) == "/s/lib/light.glsl:3: warning: unused variable");
  // NVIDIA: source(line) : message
  CHECK(mapCompileLog("1(7) : error C0000: syntax error, unexpected '}'\n", files) ==
        "/s/lib/light.glsl:7: error C0000: syntax error, unexpected '}'\n");
  // AMD / Apple / glslang: SEVERITY: source:line: message
  CHECK(mapCompileLog("ERROR: 1:4: 'x' : undeclared identifier \n", files) ==
        "/s/lib/light.glsl:4: error: 'x' : undeclared identifier \n");
  CHECK(mapCompileLog("WARNING: 0:2: 'y' : unused\n", files) == "/s/top.frag:2: warning: 'y' : unused\n");

  // A whole log: unknown lines (summaries, blank lines, out-of-range source strings) are kept.
  const std::string log =
      "ERROR: 0:9: 'a' : undeclared identifier\r\n"
      "ERROR: 5:9: 'b' : source string 5 does not exist\r\n"
      "\r\n"
      "ERROR: 2 compilation errors.  No code generated.\r\n";
  CHECK(mapCompileLog(log, files) ==
        "/s/top.frag:9: error: 'a' : undeclared identifier\r\n"
        "ERROR: 5:9: 'b' : source string 5 does not exist\r\n"
        "\r\n"
        "ERROR: 2 compilation errors.  No code generated.\r\n");
  CHECK(mapCompileLog("", files).empty());
  CHECK(mapCompileLog("0:12(5): error: no files\n", {}) == "0:12(5): error: no files\n");
}

TEST_CASE("shader source: the stage comes from the extension") {
  CHECK(stageFromPath("a/b.vert") == ShaderStage::Vertex);
  CHECK(stageFromPath("b.frag") == ShaderStage::Fragment);
  CHECK(stageFromPath("/x/b.geom") == ShaderStage::Geometry);
  CHECK(stageFromPath("b.tesc") == ShaderStage::TessControl);
  CHECK(stageFromPath("b.tese") == ShaderStage::TessEvaluation);
  CHECK(stageFromPath("b.comp") == ShaderStage::Compute);
  CHECK(stageExtension(ShaderStage::Fragment) == ".frag");
  CHECK(stageExtension(ShaderStage::TessEvaluation) == ".tese");

  const auto message = [](const std::string& path) {
    try {
      stageFromPath(path);
    } catch (const ShaderSourceError& e) { return std::string(e.what()); }
    return std::string("<no error>");
  };
  CHECK(message("common/lighting.glsl") ==
        "'common/lighting.glsl': unknown shader stage extension '.glsl' (expected one of .vert .frag .geom .tesc "
        ".tese .comp)");
  CHECK(message("noextension") ==
        "'noextension': unknown shader stage extension '' (expected one of .vert .frag .geom .tesc .tese .comp)");
  CHECK(message("b.frag.bak") != "<no error>");
  CHECK(message("b.FRAG") != "<no error>");  // case matters, as for glslangValidator
}

TEST_CASE("paths: SHADOWLAB_ROOT overrides the configure-time source root") {
  {
    ScopedEnv env("SHADOWLAB_ROOT", std::nullopt);
    CHECK(sourceRoot() == test::sourceTree());
    CHECK(shaderRoot() == test::sourceTree() + "/shaders");
    CHECK(textureRoot() == test::sourceTree() + "/textures");
  }
  {
    ScopedEnv env("SHADOWLAB_ROOT", std::string("/opt/shadowlab"));
    CHECK(sourceRoot() == "/opt/shadowlab");
    CHECK(shaderRoot() == "/opt/shadowlab/shaders");
    CHECK(textureRoot() == "/opt/shadowlab/textures");
  }
  {
    ScopedEnv env("SHADOWLAB_ROOT", std::string("/opt/shadowlab//"));
    CHECK(shaderRoot() == "/opt/shadowlab/shaders");
  }
  {
    ScopedEnv env("SHADOWLAB_ROOT", std::string(""));  // set but empty: as if unset
    CHECK(shaderRoot() == test::sourceTree() + "/shaders");
  }
}

TEST_CASE(
    "shader source: includes nest at most kMaxIncludeDepth deep, 8,000 (which overflowed the stack) is an error") {
  TempDir dir;
  // chain(n): top.frag includes f1.glsl, which includes f2.glsl, ... n files in all.
  auto chain = [&](std::size_t files) {
    dir.write("f" + std::to_string(files - 1) + ".glsl", "float deepest;\n");
    for (std::size_t i = files - 1; i-- > 1;)
      dir.write("f" + std::to_string(i) + ".glsl", "#include \"f" + std::to_string(i + 1) + ".glsl\"\n");
    return dir.write("top.frag", "#version 410 core\n#include \"f1.glsl\"\n");
  };
  const ShaderSource deepest = loadShaderSource(chain(kMaxIncludeDepth), {});
  CHECK(deepest.files.size() == kMaxIncludeDepth);
  checkLineAttribution(deepest);
  const std::string limit = std::to_string(kMaxIncludeDepth);
  CHECK(errorOf(chain(kMaxIncludeDepth + 1)) ==
        dir / ("f" + std::to_string(kMaxIncludeDepth - 1) + ".glsl") + ":1: #include nested deeper than " + limit +
            " files (from " + dir / "top.frag" + "); is a chain of includes generated by mistake?");
  CHECK(errorOf(chain(8000)).find(":1: #include nested deeper than " + limit + " files") != std::string::npos);
}

TEST_CASE("shader source: a compile log with a 30,000-character line maps without recursion (std::regex segfaulted)") {
  const std::vector<std::string> files{"/s/top.frag"};
  for (std::size_t length : {std::size_t(30000), std::size_t(1) << 20}) {
    CAPTURE(length);
    const std::string identifier(length, 'x');
    CHECK(mapCompileLog("0:3(7): error: `" + identifier + "' undeclared\n", files) ==
          "/s/top.frag:3: error: `" + identifier + "' undeclared\n");
    CHECK(mapCompileLog("ERROR: 0:3: '" + identifier + "' : undeclared identifier", files) ==
          "/s/top.frag:3: error: '" + identifier + "' : undeclared identifier");
    const std::string digits(length, '7');  // a location too long to be one: kept as it is
    CHECK(mapCompileLog("0:" + digits + "(1): error: x\n", files) == "0:" + digits + "(1): error: x\n");
  }
}

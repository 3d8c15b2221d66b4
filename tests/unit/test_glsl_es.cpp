// The browser build's shader path, GL-free: core/glsl_es (GLSL 4.10 as GLSL ES 3.00) and
// core/shader_source's loadShaderSources (one stage's files as one source, as WebGL2 links them).
// Expected texts written out by hand from the rule that `#line N` makes the NEXT line number N.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/glsl_es.hpp"
#include "core/shader_source.hpp"

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {
const std::string kPrecisions =
    "precision highp float; precision highp int; precision highp sampler2DShadow; precision highp sampler2DArray; "
    "precision highp sampler2DArrayShadow; precision highp samplerCubeShadow; precision highp sampler3D; "
    "precision highp usampler2D; precision highp isampler2D; precision highp usampler2DArray;";

struct Scratch {
  fs::path root = fs::temp_directory_path() / ("shadowlab_glsl_es_" + std::to_string(getpid()));
  Scratch() {
    fs::remove_all(root);
    fs::create_directories(root);
    root = fs::canonical(root);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(root / name, std::ios::binary) << text;
    return (root / name).string();
  }
};
}  // namespace

TEST_CASE("glsl_es: the version line, the precisions, SHADOWLAB_GLES, no `precise`, and the numbering kept") {
  const std::string in = "#version 410 core\nuniform float a;\nvoid main() {}\n";
  CHECK(toGlslEs(in) == "#version 300 es\n" + kPrecisions +
                            "\n#define SHADOWLAB_GLES 1\n#define precise\n#line 2\nuniform float a;\nvoid main() {}\n");
}

TEST_CASE("glsl_es: comments before #version stay before it; #line names the line after it") {
  const std::string in = "// a comment\n#version 410 core\nfloat f;\n";
  CHECK(toGlslEs(in) == "// a comment\n#version 300 es\n" + kPrecisions +
                            "\n#define SHADOWLAB_GLES 1\n#define precise\n#line 3\nfloat f;\n");
}

TEST_CASE("glsl_es: #extension lines move up to the version, leaving a blank line behind") {
  const std::string in = "#version 410 core\nfloat f;\n  #extension GL_X : enable\nfloat g;\n";
  CHECK(toGlslEs(in) == "#version 300 es\n  #extension GL_X : enable\n" + kPrecisions +
                            "\n#define SHADOWLAB_GLES 1\n#define precise\n#line 2\nfloat f;\n\nfloat g;\n");
}

TEST_CASE("glsl_es: a desktop ARB extension's line goes, wherever it stands") {
  const std::string in = "#version 410 core\n#ifdef QUAD\n#extension GL_ARB_derivative_control : require\n#endif\n";
  CHECK(toGlslEs(in) == "#version 300 es\n" + kPrecisions +
                            "\n#define SHADOWLAB_GLES 1\n#define precise\n#line 2\n#ifdef QUAD\n\n#endif\n");
}

TEST_CASE("glsl_es: a source without #version is refused") {
  CHECK_THROWS_AS(toGlslEs("void main() {}\n"), std::invalid_argument);
}

TEST_CASE("loadShaderSources: one stage's files as one source, includes once, a repeated uniform once") {
  Scratch s;
  s.write("common.glsl", "struct Light { vec3 p; };\n");
  const std::string a = s.write("a.frag",
                                "#version 410 core\n#include \"common.glsl\"\nuniform Light uLights[4];\n"
                                "float vis();\nvoid main() { vis(); }\n");
  const std::string b = s.write("b.frag",
                                "#version 410 core\n#include \"common.glsl\"\nuniform Light uLights[4];\n"
                                "uniform float uOwn;\nfloat vis() { return uOwn; }\n");
  const ShaderSource merged = loadShaderSources({a, b}, {});
  REQUIRE(merged.files.size() == 3);  // a, common.glsl, b
  CHECK(merged.files[0] == a);
  CHECK(merged.files[2] == b);
  const std::string text = merged.text;
  CHECK(text.find("#version 410 core") == 0);
  CHECK(text.find("#version", 1) == std::string::npos);            // b's version line blanked
  CHECK(text.find("struct Light") == text.rfind("struct Light"));  // common.glsl once
  CHECK(text.find("uniform Light uLights[4];") == text.rfind("uniform Light uLights[4];"));
  CHECK(text.find("uniform float uOwn;") != std::string::npos);  // b's own uniform kept
  CHECK(text.find("#line 1 2\n") != std::string::npos);          // b numbered as source string 2
  CHECK(text.find("float vis() { return uOwn; }") > text.find("void main()"));
}

TEST_CASE("loadShaderSources: a single file is loadShaderSource's text; none is an error") {
  Scratch s;
  const std::string a = s.write("a.frag", "#version 410 core\nvoid main() {}\n");
  CHECK(loadShaderSources({a}, {}).text == loadShaderSource(a, {}).text);
  CHECK_THROWS_AS(loadShaderSources({}, {}), ShaderSourceError);
}

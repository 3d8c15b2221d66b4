#include "core/glsl_es.hpp"

#include <cctype>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace shadowlab {
namespace {

// The directive a line holds ("version", "extension"), or "".
std::string directive(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return "";
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos) return "";
  std::size_t end = i;
  while (end < line.size() && std::isalpha(static_cast<unsigned char>(line[end]))) ++end;
  return line.substr(i, end - i);
}

constexpr const char* kPrecisions =
    "precision highp float; precision highp int; precision highp sampler2DShadow; precision highp sampler2DArray; "
    "precision highp sampler2DArrayShadow; precision highp samplerCubeShadow; precision highp sampler3D; "
    "precision highp usampler2D; precision highp isampler2D; precision highp usampler2DArray;";

}  // namespace

std::string toGlslEs(const std::string& source) {
  std::vector<std::string> lines;
  std::istringstream in(source);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::size_t version = lines.size();
  for (std::size_t i = 0; i < lines.size() && version == lines.size(); ++i)
    if (directive(lines[i]) == "version") version = i;
  if (version == lines.size())
    throw std::invalid_argument("toGlslEs: the shader has no #version line (expand it with loadShaderSource first)");
  std::vector<std::string> extensions;
  // An ARB extension is desktop OpenGL's, never WebGL2's: its line goes (the shader uses it only
  // where gl::caps() found it, under a define the browser build never sets: PCSS's QUAD_SEARCH).
  for (std::size_t i = version + 1; i < lines.size(); ++i)
    if (directive(lines[i]) == "extension") {
      if (lines[i].find("GL_ARB_") == std::string::npos) extensions.push_back(lines[i]);
      lines[i].clear();
    }
  std::string out;
  for (std::size_t i = 0; i < version; ++i) out += lines[i] + '\n';
  out += "#version 300 es\n";
  for (const std::string& e : extensions) out += e + '\n';
  // GLSL ES 3.00 has no `precise` (3.20 does): the desktop shaders' qualifier is dropped.
  out += std::string(kPrecisions) + "\n#define SHADOWLAB_GLES 1\n#define precise\n";
  out += "#line " + std::to_string(version + 2) + '\n';  // GLSL numbers lines from 1: the next one's number
  for (std::size_t i = version + 1; i < lines.size(); ++i) out += lines[i] + '\n';
  return out;
}

}  // namespace shadowlab

// shader_check: offline validation of the course's GLSL, so a typo in a shader fails `ctest` on a
// machine without a GPU instead of failing at run time in a lesson.
//
//   shader_check [--include DIR]... SHADER...
//
// Each SHADER is expanded with loadShaderSource (include directories: every --include, then the
// shader root), written to a temporary file with the stage's extension, and handed to
// glslangValidator. Diagnostics are printed as "original/file.glsl:line: message" — the same
// mapping the GL layer applies to driver logs — so they point at the file to edit, not at the
// expanded temporary. Exit status: 0 all valid, 1 any shader invalid, 2 bad usage.
#include "core/paths.hpp"
#include "core/shader_source.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#ifndef SHADOWLAB_GLSLANG_VALIDATOR
#error "SHADOWLAB_GLSLANG_VALIDATOR (path to glslangValidator) must be defined by the build"
#endif

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

// The course targets OpenGL 4.1 core (the newest macOS supports), so every stage must say so
// explicitly; without it the driver would fall back to GLSL 1.10 and accept different code.
constexpr const char* kRequiredVersion = "#version 410 core";

std::string shellQuote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) {
    if (c == '\'') quoted += "'\\''";
    else quoted += c;
  }
  return quoted + "'";
}

std::string firstLine(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
  return line;
}

// Runs the validator on `file`; returns its combined output and sets `ok` only on a clean exit 0
// (a crash of the validator is a failure, not a pass).
std::string runValidator(const fs::path& file, bool& ok) {
  const std::string command = shellQuote(SHADOWLAB_GLSLANG_VALIDATOR) + " " + shellQuote(file.string()) + " 2>&1";
  std::string output;
  ok = false;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "cannot run " + std::string(SHADOWLAB_GLSLANG_VALIDATOR) + "\n";
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = pclose(pipe);
  ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (status != -1 && WIFSIGNALED(status)) {
    output += "glslangValidator killed by signal " + std::to_string(WTERMSIG(status)) + "\n";
  }
  return output;
}

// glslangValidator echoes the name of the file it checked; that is our temporary, which means
// nothing to the reader, so it is dropped. Everything else is mapped back to the original files.
std::string cleanLog(const std::string& log, const fs::path& temporary, const std::vector<std::string>& files) {
  std::string kept;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    const std::string line = log.substr(start, end - start);
    if (line != temporary.string() && !line.empty()) kept += line + "\n";
    start = end + 1;
  }
  return mapCompileLog(kept, files);
}

bool checkShader(const std::string& path, const std::vector<std::string>& includeDirs, int serial) {
  try {
    const ShaderStage stage = stageFromPath(path);
    if (firstLine(path) != kRequiredVersion) {
      std::cerr << path << ":1: error: the first line must be '" << kRequiredVersion << "'\n";
      return false;
    }
    const ShaderSource source = loadShaderSource(path, includeDirs);

    // The pid and a serial keep parallel ctest runs from overwriting each other's temporaries.
    const fs::path temporary =
        fs::temp_directory_path() / ("shader_check-" + std::to_string(getpid()) + "-" + std::to_string(serial) +
                                     std::string(stageExtension(stage)));
    {
      std::ofstream out(temporary, std::ios::binary);
      out << source.text;
      if (!out) {
        std::cerr << path << ": error: cannot write temporary " << temporary << "\n";
        return false;
      }
    }
    bool ok = false;
    const std::string log = runValidator(temporary, ok);
    std::error_code ec;
    fs::remove(temporary, ec);
    std::cerr << cleanLog(log, temporary, source.files);
    if (!ok) {
      std::cerr << path << ": error: glslangValidator rejected the shader\n";
      return false;
    }
    return true;
  } catch (const ShaderSourceError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return false;
  }
}

int usage() {
  std::cerr << "usage: shader_check [--include DIR]... SHADER...\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> includeDirs;
  std::vector<std::string> shaders;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--include") {
      if (i + 1 >= argc) return usage();
      includeDirs.push_back(argv[++i]);
    } else if (arg == "-h" || arg == "--help") {
      usage();
      return 0;
    } else if (!arg.empty() && arg[0] == '-') {
      return usage();
    } else {
      shaders.push_back(arg);
    }
  }
  if (shaders.empty()) return usage();
  includeDirs.push_back(shaderRoot());

  int failures = 0;
  for (std::size_t i = 0; i < shaders.size(); ++i) {
    if (!checkShader(shaders[i], includeDirs, static_cast<int>(i))) ++failures;
  }
  if (failures == 0) std::cout << "shader_check: " << shaders.size() << " shader(s) valid\n";
  return failures == 0 ? 0 : 1;
}

// shader_check: offline validation of the course's GLSL, so a typo in a shader fails `ctest` on a
// machine without a GPU instead of failing at run time in a lesson.
//
//   shader_check [--include DIR]... SHADER...
//   shader_check --variants LOG [--variants LOG]... [--root DIR] [--allow NAME]...
//   shader_check --es ...   either form, each shader as the browser build compiles it
//
// Each SHADER is expanded with loadShaderSource (include directories: every --include, then the
// shader root), written to a temporary file with the stage's extension, and handed to
// glslangValidator. Diagnostics are printed as "original/file.glsl:line: message" — the same
// mapping the GL layer applies to driver logs — so they point at the file to edit, not at the
// expanded temporary. Exit status: 0 all valid, 1 any shader invalid, 2 bad usage.
//
// --variants: the shaders as the programs compile them, #ifdef branches included. Each LOG is
// what lessons run with SHADOWLAB_SHADER_VARIANTS=LOG recorded (gl/program.cpp), one program a line:
//   LABEL <tab> STAGE FILES (space-separated, relative to the shader root) [<tab> DEFINE]...
// Every unique (stage file, define set) is expanded exactly as gl::Program does (loadShaderSource
// with the shader root as include directory, then withDefines: the #defines right after
// `#version 410 core`) and validated; an error line names the define set and the LOG line that
// asked for it. Then coverage, so that a log that misses a branch cannot pass: every name an
// #if/#ifdef/#ifndef/#elif tests in any shader or include file under the root (--root DIR, default
// the shader root; GL_* and __*__, which the compiler defines, aside) must be defined by a checked
// variant of a stage that includes that file, or be named by --allow. Each gap is reported as
// "file:line: error: NAME ..." and exits 1; so does an --allow NAME that no gap needs (stale).
// The coverage figure is printed either way.
//
// --es: each expanded shader is translated to GLSL ES 3.00 (core/glsl_es.hpp) first and validated
// as WebGL2 compiles it; with --variants, the logs of the browser's lessons (no coverage check: the
// native run of every lesson's log covers the names).
#include "core/glsl_es.hpp"
#include "core/paths.hpp"
#include "core/shader_source.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#ifndef SHADOWLAB_GLSLANG_VALIDATOR
#error "SHADOWLAB_GLSLANG_VALIDATOR (path to glslangValidator) must be defined by the build"
#endif

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

bool g_es = false;  // --es: validate as GLSL ES 3.00 (WebGL2), translated by toGlslEs

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
// nothing to the reader, so it is dropped. Everything else is mapped back to the original files,
// and each line names the variant (`suffix`), since the same line is valid in another.
std::string cleanLog(const std::string& log, const fs::path& temporary, const std::vector<std::string>& files,
                     const std::string& suffix) {
  std::string kept;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    const std::string line = log.substr(start, end - start);
    if (line != temporary.string() && !line.empty()) kept += line + "\n";
    start = end + 1;
  }
  const std::string mapped = mapCompileLog(kept, files);
  if (suffix.empty()) return mapped;
  std::string named;
  for (start = 0; start < mapped.size();) {
    const std::size_t end = mapped.find('\n', start);
    std::string line = mapped.substr(start, end - start);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    named += line + suffix + "\n";
    start = end == std::string::npos ? mapped.size() : end + 1;
  }
  return named;
}

// One stage as a program compiles it: the file, the #defines inserted after #version (none for a
// plain check) and, for the error line, what asked for it.
struct Stage {
  std::string path;
  std::vector<std::string> defines;
  std::string origin;             // "LOG:LINE (program 'LABEL')"; empty for a file named on the command line
  std::vector<std::string> more;  // --es: the program's other files of this stage, compiled as one
};

// "with defines {LIGHT_COUNT 2, PCSS}"
std::string describe(const std::vector<std::string>& defines) {
  if (defines.empty()) return "with no defines";
  std::string s;
  for (const auto& d : defines) s += (s.empty() ? "" : ", ") + d;
  return "with defines {" + s + "}";
}

// Validates one stage, its diagnostics into `err`. `files`: the files its text was expanded from
// (canonical), valid or not.
bool checkShader(const Stage& stage, const std::vector<std::string>& includeDirs, int serial,
                 std::vector<std::string>& files, std::ostream& err) {
  const std::string& path = stage.path;
  const std::string variant = stage.origin.empty() ? "" : " " + describe(stage.defines);
  try {
    const ShaderStage kind = stageFromPath(path);
    if (firstLine(path) != kRequiredVersion) {
      err << path << ":1: error: the first line must be '" << kRequiredVersion << "'\n";
      return false;
    }
    std::vector<std::string> paths{path};
    paths.insert(paths.end(), stage.more.begin(), stage.more.end());
    const ShaderSource source =
        paths.size() == 1 ? loadShaderSource(path, includeDirs) : loadShaderSources(paths, includeDirs);
    files = source.files;

    // The pid and a serial keep parallel ctest runs from overwriting each other's temporaries.
    const fs::path temporary = fs::temp_directory_path() / ("shader_check-" + std::to_string(getpid()) + "-" +
                                                            std::to_string(serial) + std::string(stageExtension(kind)));
    {
      std::ofstream out(temporary, std::ios::binary);
      const std::string text = withDefines(source.text, stage.defines);
      // --es: with what gl::Program adds where WebGL2 lacks a feature (its fallbacks in the shaders).
      out << (g_es ? toGlslEs(withDefines(
                         text, {"SHADOWLAB_NO_BORDER_CLAMP", "SHADOWLAB_NO_CLIP_DISTANCE", "SHADOWLAB_NO_DEPTH_CLAMP"}))
                   : text);
      if (!out) {
        err << path << ": error: cannot write temporary " << temporary << "\n";
        return false;
      }
    }
    bool ok = false;
    const std::string log = runValidator(temporary, ok);
    std::error_code ec;
    fs::remove(temporary, ec);
    err << cleanLog(log, temporary, source.files, variant.empty() ? "" : " [" + variant.substr(1) + "]");
    if (!ok) {
      err << path << ": error: glslangValidator rejected the shader" << variant
          << (stage.origin.empty() ? "" : " (recorded at " + stage.origin + ")") << "\n";
      return false;
    }
    return true;
  } catch (const std::invalid_argument& e) {  // toGlslEs: no #version line
    err << path << ": error: " << e.what() << "\n";
    return false;
  } catch (const ShaderSourceError& e) {
    err << "error: " << e.what() << (stage.origin.empty() ? "" : " (recorded at " + stage.origin + ")") << "\n";
    return false;
  }
}

// ---------------------------------------------------------------------------------------------
// --variants: the recorded logs

std::vector<std::string> splitOn(const std::string& s, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t end = s.find(separator); end != std::string::npos; end = s.find(separator, start)) {
    parts.push_back(s.substr(start, end - start));
    start = end + 1;
  }
  parts.push_back(s.substr(start));
  return parts;
}

// Every unique (stage file, define set) of the logs, with the first line that recorded it.
// False (and a message naming LOG:LINE) on a log that cannot be read or a malformed line.
bool readVariants(const std::vector<std::string>& logs, const std::string& root, std::vector<Stage>& stages) {
  std::set<std::pair<std::string, std::vector<std::string>>> seen;
  for (const std::string& log : logs) {
    std::ifstream in(log);
    if (!in) {
      std::cerr << "error: cannot read variants log '" << log << "'\n";
      return false;
    }
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.empty()) continue;
      std::vector<std::string> fields = splitOn(line, '\t');
      if (fields.size() < 2 || fields[1].empty()) {
        std::cerr << log << ":" << number << ": error: expected 'LABEL<tab>FILES[<tab>DEFINE]...'\n";
        return false;
      }
      const std::string origin = log + ":" + std::to_string(number) + " (program '" + fields[0] + "')";
      const std::vector<std::string> defines(fields.begin() + 2, fields.end());
      // One shader a file; with --es one a stage, its files merged as gl::Program merges them.
      // A program with a geometry stage is not built in WebGL2 (its user takes a fallback, which
      // the test names on its own command line): --es leaves it out.
      if (g_es && fields[1].find(".geom") != std::string::npos) continue;
      // Nor is PCSS's quad search, which needs fine derivatives (PcssShadows::quadSearchOn).
      if (g_es && std::find(defines.begin(), defines.end(), "QUAD_SEARCH 1") != defines.end()) continue;
      std::vector<std::vector<std::string>> units;
      for (const std::string& file : splitOn(fields[1], ' ')) {
        if (file.empty()) continue;
        auto same = std::find_if(units.begin(), units.end(),
                                 [&](const auto& u) { return stageFromPath(u.front()) == stageFromPath(file); });
        if (g_es && same != units.end()) same->push_back(file);
        else units.push_back({file});
      }
      for (const std::vector<std::string>& unit : units) {
        std::string key;
        for (const std::string& file : unit) key += file + " ";
        if (!seen.insert({key, defines}).second) continue;
        Stage stage{root + "/" + unit.front(), defines, origin, {}};
        for (std::size_t i = 1; i < unit.size(); ++i) stage.more.push_back(root + "/" + unit[i]);
        stages.push_back(std::move(stage));
      }
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// --variants: coverage of the names the shaders test

struct MacroTest {
  std::string name, file;  // file: canonical
  std::size_t line = 0;
};

bool isShaderFile(const fs::path& p) {
  static const std::set<std::string> kExtensions{".vert", ".frag", ".geom", ".tesc", ".tese", ".comp", ".glsl"};
  return kExtensions.count(p.extension().string()) != 0;
}

// The names a conditional directive's line tests: every identifier but `defined`, and but those the
// compiler itself defines (GL_ARB_..., GL_core_profile, __VERSION__), which no program sets.
std::vector<std::string> testedNames(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return {};
  i = line.find_first_not_of(" \t", i + 1);
  std::size_t end = i;
  while (end < line.size() && std::isalpha(static_cast<unsigned char>(line[end]))) ++end;
  const std::string directive = i == std::string::npos ? "" : line.substr(i, end - i);
  if (directive != "if" && directive != "ifdef" && directive != "ifndef" && directive != "elif") return {};
  std::string expression = line.substr(end, line.find("//", end) - end);
  expression = expression.substr(0, expression.find("/*"));
  std::vector<std::string> names;
  for (std::size_t k = 0; k < expression.size();) {
    const auto word = [&](std::size_t j) {
      return j < expression.size() && (std::isalnum(static_cast<unsigned char>(expression[j])) || expression[j] == '_');
    };
    if (!word(k)) {
      ++k;
      continue;
    }
    std::size_t stop = k;
    while (word(stop) || (stop < expression.size() && expression[stop] == '.')) ++stop;  // 1.5e3, 0x1Fu whole
    const std::string token = expression.substr(k, stop - k);
    const bool builtin = token.rfind("GL_", 0) == 0 || token.rfind("__", 0) == 0;
    const bool seen = std::find(names.begin(), names.end(), token) != names.end();  // defined(A) && A > 1
    if (!std::isdigit(static_cast<unsigned char>(token[0])) && token != "defined" && !builtin && !seen)
      names.push_back(token);
    k = stop;
  }
  return names;
}

// Every conditional directive's names in every shader and include file under `root`, in file order.
std::vector<MacroTest> scanMacroTests(const std::string& root) {
  std::vector<fs::path> paths;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file() && isShaderFile(entry.path())) paths.push_back(fs::canonical(entry.path()));
  std::sort(paths.begin(), paths.end());
  std::vector<MacroTest> tests;
  for (const fs::path& path : paths) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    bool inComment = false;  // a directive inside /* */ tests nothing
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (!inComment)
        for (const std::string& name : testedNames(line)) tests.push_back({name, path.string(), number});
      for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        if (!inComment && line.compare(k, 2, "//") == 0) break;
        if (line.compare(k, 2, inComment ? "*/" : "/*") == 0) {
          inComment = !inComment;
          ++k;
        }
      }
    }
  }
  return tests;
}

// Reports each test of a name that no checked variant of a stage including its file defines, and
// the figure; false when one is neither covered nor allowed, or when an allowed name needs no allowing.
bool checkCoverage(const std::vector<MacroTest>& tests, const std::set<std::pair<std::string, std::string>>& defined,
                   const std::set<std::string>& allowed) {
  std::set<std::string> names, gapNames, allowedNames;
  std::size_t covered = 0;
  for (const MacroTest& t : tests) {
    names.insert(t.name);
    if (defined.count({t.file, t.name}) != 0) {
      ++covered;
    } else if (allowed.count(t.name) != 0) {
      allowedNames.insert(t.name);
    } else {
      gapNames.insert(t.name);
      std::cerr << t.file << ":" << t.line << ": error: " << t.name
                << " is tested here, but no recorded variant of a shader including this file defines it: the"
                   " branch is never validated (record a run that reaches it, or allowlist it with the reason)\n";
    }
  }
  std::cout << "shader_check: coverage: " << covered << " of " << tests.size() << " conditional tests see their name"
            << " defined by a checked variant; names " << names.size() - gapNames.size() - allowedNames.size()
            << " covered, " << allowedNames.size() << " allowlisted, " << gapNames.size() << " uncovered, of "
            << names.size() << "\n";
  // An exception no test needs any more goes, so the allowlist cannot outlive its reason.
  bool stale = false;
  for (const std::string& name : allowed) {
    if (allowedNames.count(name) != 0) continue;
    std::cerr << "error: --allow " << name << ": no uncovered test of it is left; drop it from the allowlist\n";
    stale = true;
  }
  return gapNames.empty() && !stale;
}

int checkVariants(const std::vector<std::string>& logs, const std::string& root, const std::set<std::string>& allowed) {
  std::vector<Stage> stages;
  if (!readVariants(logs, root, stages)) return 1;
  // One validator per core (hundreds of variants), the reports printed in the logs' order.
  std::vector<std::vector<std::string>> files(stages.size());
  std::vector<std::string> reports(stages.size());
  std::vector<char> valid(stages.size(), 0);
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> workers(std::max(1u, std::thread::hardware_concurrency()));
  for (std::thread& worker : workers) {
    worker = std::thread([&] {
      for (std::size_t i = next++; i < stages.size(); i = next++) {
        std::ostringstream err;
        valid[i] = checkShader(stages[i], {root}, static_cast<int>(i), files[i], err);
        reports[i] = err.str();
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  std::set<std::pair<std::string, std::string>> defined;  // (canonical file, name)
  std::size_t failures = 0;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    std::cerr << reports[i];
    failures += valid[i] ? 0 : 1;
    // A variant that failed still counts as checked: its error is the report.
    for (const std::string& define : stages[i].defines)
      for (const std::string& file : files[i]) defined.insert({file, define.substr(0, define.find_first_of(" \t("))});
  }
  std::cout << "shader_check: " << stages.size() - failures << " of " << stages.size()
            << " recorded (stage file, define set) variant(s) valid\n";
  const bool covered = g_es || checkCoverage(scanMacroTests(root), defined, allowed);
  return failures == 0 && covered ? 0 : 1;
}

int usage() {
  std::cerr << "usage: shader_check [--include DIR]... SHADER...\n"
               "       shader_check --variants LOG [--variants LOG]... [--root DIR] [--allow NAME]...\n"
               "       shader_check --es (either form: as GLSL ES 3.00, the browser's)\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> includeDirs, shaders, logs;
  std::set<std::string> allowed;
  std::string root;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool valued = arg == "--include" || arg == "--variants" || arg == "--root" || arg == "--allow";
    if (valued && i + 1 >= argc) return usage();
    if (arg == "--include") includeDirs.push_back(argv[++i]);
    else if (arg == "--variants") logs.push_back(argv[++i]);
    else if (arg == "--root") root = argv[++i];
    else if (arg == "--allow") allowed.insert(argv[++i]);
    else if (arg == "--es") g_es = true;
    else if (arg == "-h" || arg == "--help") {
      usage();
      return 0;
    } else if (!arg.empty() && arg[0] == '-') return usage();
    else shaders.push_back(arg);
  }
  if (!logs.empty()) {
    if (!shaders.empty() || !includeDirs.empty()) return usage();
    return checkVariants(logs, root.empty() ? shaderRoot() : root, allowed);
  }
  if (shaders.empty() || !root.empty() || !allowed.empty()) return usage();
  includeDirs.push_back(shaderRoot());

  int failures = 0;
  for (std::size_t i = 0; i < shaders.size(); ++i) {
    std::vector<std::string> files;
    if (!checkShader({shaders[i], {}, {}}, includeDirs, static_cast<int>(i), files, std::cerr)) ++failures;
  }
  if (failures == 0) std::cout << "shader_check: " << shaders.size() << " shader(s) valid\n";
  return failures == 0 ? 0 : 1;
}

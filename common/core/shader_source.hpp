#pragma once
// GLSL source loading for the GL layer: a small, line-based preprocessor for `#include "file"`
// (GLSL has no includes of its own), plus what a hot-reloading, error-reporting shader program
// needs around it: file stamps to poll, `#line` bookkeeping so driver logs point back at the real
// files, and the shader stage implied by a file name. GL-free so it is unit-tested without a GPU.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// Every failure to produce a source text: missing files, malformed or cyclic includes, unknown
// stage extensions. The message always names the file (and line, where there is one).
class ShaderSourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One file the expanded text was built from, with the write time seen when it was read.
struct FileStamp {
  std::string path;
  std::filesystem::file_time_type writeTime;
  bool onDisk = true;  // false: virtual text (core/shader_files.hpp), which never changes on disk
};

struct ShaderSource {
  // The expanded source, ready for glShaderSource. `#line N S` directives follow every include
  // boundary; S indexes `files`.
  std::string text;
  // Source-string numbers: files[S] is the canonical path of source string S; files[0] is the
  // top-level file. Hand this to mapCompileLog.
  std::vector<std::string> files;
  // Every file read (the top file and each include, once), for hot-reload polling.
  std::vector<FileStamp> dependencies;
};

// Reads `path` and expands `#include "relative/path"` recursively. An include is looked up
// relative to the including file first, then in each of `includeDirs` in order. A file is expanded
// at most once per program (by canonical path), so shared headers need no guards; an include of a
// file still being expanded is a cycle and an error. The top file's `#version` line is emitted
// first, as GLSL requires.
//
// A file or include that does not exist on disk is looked up as virtual text
// (core/shader_files.hpp: generated or sealed GLSL) by its path relative to an include directory.
//
// Limits, because this is not a full preprocessor: includes inside /* */ comments are ignored,
// but those inside #if blocks are expanded regardless of the condition. Includes nest at most
// kMaxIncludeDepth files deep (an error naming the file and line past it).
inline constexpr std::size_t kMaxIncludeDepth = 64;
ShaderSource loadShaderSource(const std::string& path, const std::vector<std::string>& includeDirs);
// Several files of one stage as ONE source, for GLSL ES (WebGL2), which links a single shader per
// stage where desktop GL links several (a technique's visibility file beside the scene shader):
// each file after the first is expanded in turn, its #version line blanked, includes expanded once
// across all of them, and a `uniform` declaration that an earlier file made word for word left out
// (desktop GL links the two as one uniform; in one source the second would be a redefinition).
ShaderSource loadShaderSources(const std::vector<std::string>& paths, const std::vector<std::string>& includeDirs);

// `text` (a loadShaderSource result, #version first) specialised by `defines` ("NAME" or "NAME VALUE"):
// one "#define NAME VALUE" line each right after #version, then a #line so logs keep the file's own
// numbering. gl::Program compiles this text and shader_check --variants validates the same text.
std::string withDefines(const std::string& text, const std::vector<std::string>& defines);

// True when any dependency was modified or removed since `source` was loaded.
bool dependenciesChanged(const ShaderSource& source);

// Rewrites the locations in a driver's compile log from "source-string:line" to "path:line: message"
// using the `files` table of a ShaderSource. Understands Mesa ("0:12(5): error: ..."), NVIDIA
// ("0(12) : error C0000: ...") and AMD / Apple / glslang ("ERROR: 0:12: ..."); any other line,
// or one naming a source string outside `files`, is kept unchanged. Linear in the log's length,
// with no recursion: any line length is fine.
std::string mapCompileLog(const std::string& log, const std::vector<std::string>& files);

enum class ShaderStage { Vertex, Fragment, Geometry, TessControl, TessEvaluation, Compute };

// The stage named by the file extension: .vert .frag .geom .tesc .tese .comp (the convention
// glslangValidator also uses). Throws ShaderSourceError, listing the valid extensions, otherwise.
ShaderStage stageFromPath(const std::string& path);

// The extension stageFromPath maps to `stage`, with the dot (".frag").
std::string_view stageExtension(ShaderStage stage);

}  // namespace shadowlab

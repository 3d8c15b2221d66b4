#include "core/shader_source.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>
#include <utility>

#include "core/shader_files.hpp"

namespace fs = std::filesystem;

namespace shadowlab {

namespace {

// Splits on '\n' and drops a trailing '\r' so files saved with CRLF endings keep their line
// numbers and do not leak '\r' into directives. A final newline does not start an extra line.
std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

bool readFile(const fs::path& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return false;
  out = buffer.str();
  return true;
}

std::size_t skipSpaces(const std::string& s, std::size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  return i;
}

// If `line` is a preprocessor directive, its name ("include", "version"), and in `rest` the index
// just after the name; "" otherwise.
std::string directiveName(const std::string& line, std::size_t& rest) {
  std::size_t i = skipSpaces(line, 0);
  if (i >= line.size() || line[i] != '#') return {};
  i = skipSpaces(line, i + 1);
  std::size_t begin = i;
  while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_')) ++i;
  rest = i;
  return line.substr(begin, i - begin);
}

// Tracks /* */ comments across lines so an #include that is commented out is left alone.
// GLSL has no string or character literals, so comment markers cannot hide inside one.
void advanceCommentState(const std::string& line, bool& inBlockComment) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (inBlockComment) {
      if (line.compare(i, 2, "*/") == 0) {
        inBlockComment = false;
        ++i;
      }
    } else if (line.compare(i, 2, "//") == 0) {
      return;
    } else if (line.compare(i, 2, "/*") == 0) {
      inBlockComment = true;
      ++i;
    }
  }
}

std::string location(const std::string& file, std::size_t line) { return file + ":" + std::to_string(line); }

class Expander {
 public:
  explicit Expander(const std::vector<std::string>& includeDirs) : includeDirs_(includeDirs) {}

  ShaderSource run(const std::string& path) {
    expand(locate(path), /*top=*/true);
    return std::move(result_);
  }

  // loadShaderSources: the first file as run() does, then each other one appended, its #version
  // line blank and its repeated uniform declarations left out.
  ShaderSource runAll(const std::vector<std::string>& paths) {
    for (std::size_t i = 0; i < paths.size(); ++i) {
      merging_ = i > 0;
      const fs::path file = locate(paths[i]);
      if (expanded_.count(file) == 0) expand(file, /*top=*/i == 0);
    }
    return std::move(result_);
  }

 private:
  fs::path locate(const std::string& path) const {
    std::error_code ec;
    fs::path canonical = fs::canonical(path, ec);
    if (ec || !fs::is_regular_file(canonical, ec)) {
      canonical = virtualPath(fs::path(path)).value_or(fs::path());
      if (canonical.empty()) throw ShaderSourceError("cannot open shader file '" + path + "'");
    }
    return canonical;
  }

  // While merging (runAll): a line this merged text must drop, a blank kept in its place.
  bool dropWhenMerging(const std::string& line, const std::string& directive) {
    if (directive == "version") return merging_;
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 8, "uniform ") != 0) return false;
    const bool seen = !uniforms_.insert(line.substr(start)).second;
    return merging_ && seen;
  }

  void expand(const fs::path& file, bool top) {
    const auto standIn = standIns_.find(file);
    const fs::path source = standIn != standIns_.end() ? standIn->second : file;  // what is read
    const std::string name = source.string();
    std::string content;
    // Stamp before reading: an edit landing between the two is then seen as a change by the
    // next poll instead of being missed.
    std::error_code ec;
    const fs::file_time_type stamp = fs::last_write_time(source, ec);
    const std::optional<std::string> text = ec ? virtualText(source) : std::nullopt;
    if (text) content = *text;
    else if (ec || !readFile(source, content)) throw ShaderSourceError("cannot read shader file '" + name + "'");

    const std::size_t index = result_.files.size();
    result_.files.push_back(name);
    result_.dependencies.push_back({name, stamp, !text});
    expanded_.insert(file);
    stack_.push_back(file);

    const std::vector<std::string> lines = splitLines(content);
    std::size_t first = 0;  // index of the first line still to emit
    if (top) first = emitVersionFirst(lines);
    else if (index != 0) emitLine(1, index);

    bool inBlockComment = false;
    for (std::size_t i = first; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      const std::size_t lineNumber = i + 1;
      std::size_t rest = 0;
      const std::string directive = inBlockComment ? "" : directiveName(line, rest);
      if (!inBlockComment && dropWhenMerging(line, directive)) {
        out() += '\n';
        continue;
      }
      if (directive == "include") {
        const std::string target = parseIncludeTarget(line, rest, name, lineNumber);
        if (includeFile(target, file, lineNumber)) {
          emitLine(lineNumber + 1, index);  // back in this file, after the directive
        } else {
          out() += '\n';  // already expanded: a blank keeps the numbering without a #line
        }
        continue;
      }
      if (top && versionLine_ == i) {
        out() += '\n';  // hoisted to the top; blank keeps the line numbers of what follows
        advanceCommentState(line, inBlockComment);
        continue;
      }
      out() += line;
      out() += '\n';
      advanceCommentState(line, inBlockComment);
    }
    stack_.pop_back();
  }

  // GLSL requires #version before anything but comments and whitespace, so it is emitted first
  // even when comments precede it in the file; the `#line` after it restores the numbering.
  // Returns the first line index still to emit.
  std::size_t emitVersionFirst(const std::vector<std::string>& lines) {
    bool inBlockComment = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::size_t rest = 0;
      if (!inBlockComment && directiveName(lines[i], rest) == "version") {
        versionLine_ = i;
        out() += lines[i];
        out() += '\n';
        if (i == 0) {
          emitLine(2, 0);
          return 1;
        }
        emitLine(1, 0);
        return 0;
      }
      advanceCommentState(lines[i], inBlockComment);
    }
    return 0;  // no #version: the driver's default applies and numbering already starts at 1
  }

  std::string parseIncludeTarget(const std::string& line, std::size_t rest, const std::string& file,
                                 std::size_t lineNumber) {
    const auto malformed = [&] {
      return ShaderSourceError(location(file, lineNumber) +
                               ": malformed #include (expected #include \"file\"): " + line);
    };
    std::size_t i = skipSpaces(line, rest);
    if (i >= line.size() || line[i] != '"') throw malformed();
    const std::size_t close = line.find('"', i + 1);
    if (close == std::string::npos || close == i + 1) throw malformed();
    std::string target = line.substr(i + 1, close - i - 1);
    std::size_t after = skipSpaces(line, close + 1);
    if (after < line.size() && line.compare(after, 2, "//") != 0 && line.compare(after, 2, "/*") != 0) {
      throw malformed();
    }
    return target;
  }

  // Expands `target` in place; false when it was already expanded earlier in this program.
  bool includeFile(const std::string& target, const fs::path& includer, std::size_t lineNumber) {
    const fs::path resolved = resolve(target, includer, lineNumber);
    const auto onStack = std::find(stack_.begin(), stack_.end(), resolved);
    if (onStack != stack_.end()) {
      std::string chain;
      for (auto it = onStack; it != stack_.end(); ++it) chain += it->string() + " -> ";
      chain += resolved.string();
      throw ShaderSourceError(location(includer.string(), lineNumber) + ": #include cycle: " + chain);
    }
    if (expanded_.count(resolved) != 0) return false;
    // Each level is a stack frame: 8,000 nested files overflowed the stack. Real shaders nest a few.
    if (stack_.size() >= kMaxIncludeDepth)
      throw ShaderSourceError(location(includer.string(), lineNumber) + ": #include nested deeper than " +
                              std::to_string(kMaxIncludeDepth) + " files (from " + stack_.front().string() +
                              "); is a chain of includes generated by mistake?");
    expand(resolved, /*top=*/false);
    return true;
  }

  fs::path resolve(const std::string& target, const fs::path& includer, std::size_t lineNumber) {
    std::vector<fs::path> bases{includer.parent_path()};
    for (const std::string& dir : includeDirs_) bases.emplace_back(dir);
    const fs::path relative(target);
    if (relative.is_absolute()) bases.assign(1, fs::path());  // `/` ignores the base anyway
    std::string searched;
    for (const fs::path& base : bases) {
      const fs::path candidate = base / relative;
      std::error_code ec;
      if (fs::is_regular_file(candidate, ec)) {
        fs::path canonical = fs::canonical(candidate, ec);
        if (!ec) return canonical;
      }
      searched += (searched.empty() ? "" : ", ") + (base.empty() ? candidate.string() : base.string());
    }
    for (const fs::path& base : bases)
      if (std::optional<fs::path> v = virtualPath(base / relative)) return *v;
    for (const fs::path& base : bases)
      if (std::optional<fs::path> v = standIn(base / relative)) return *v;
    throw ShaderSourceError(location(includer.string(), lineNumber) + ": cannot find include \"" + target +
                            "\" (searched " + searched + ")");
  }

  // `p` relative to an include directory, when that names virtual text: its path and its text.
  std::optional<std::pair<fs::path, std::string>> findVirtual(const fs::path& p) const {
    for (const std::string& dir : includeDirs_) {
      std::error_code ec;
      const fs::path root = fs::weakly_canonical(dir, ec);
      const fs::path rel = fs::weakly_canonical(p, ec).lexically_relative(root);
      if (ec || rel.empty() || *rel.begin() == "..") continue;
      if (std::optional<std::string> text = virtualShaderText(rel.generic_string()))
        return std::make_pair(root / rel, std::move(*text));
    }
    return std::nullopt;
  }
  // A withheld file (absent: the student handout) resolves to its own path, read from its stand-in
  // on disk, the student's exercises.glsl beside it: include-once keeps the two apart as in the
  // instructor's tree (`#ifdef STUDENT #include "exercises.glsl" #else #include
  // "exercises_reference.glsl"` expands the student's text in both branches). Noted, so the lesson
  // says whose code it draws.
  std::optional<fs::path> standIn(const fs::path& p) {
    for (const std::string& dir : includeDirs_) {
      std::error_code ec;
      const fs::path root = fs::weakly_canonical(dir, ec);
      const fs::path rel = fs::weakly_canonical(p, ec).lexically_relative(root);
      if (ec || rel.empty() || *rel.begin() == ".." || !shaderWithheld(rel.generic_string())) continue;
      const fs::path file = root / withheldStandIn(rel.generic_string());
      if (!fs::is_regular_file(file, ec)) continue;
      noteWithheldReplaced(rel.generic_string());
      standIns_[root / rel] = fs::canonical(file, ec);
      return root / rel;
    }
    return std::nullopt;
  }
  std::optional<fs::path> virtualPath(const fs::path& p) const {
    if (auto v = findVirtual(p)) return v->first;
    return std::nullopt;
  }
  std::optional<std::string> virtualText(const fs::path& p) const {
    if (auto v = findVirtual(p)) return v->second;
    return std::nullopt;
  }

  void emitLine(std::size_t line, std::size_t sourceIndex) {
    out() += "#line " + std::to_string(line) + " " + std::to_string(sourceIndex) + "\n";
  }

  std::string& out() { return result_.text; }

  const std::vector<std::string>& includeDirs_;
  ShaderSource result_;
  std::vector<fs::path> stack_;            // files being expanded, outermost first: the cycle check
  std::set<fs::path> expanded_;            // every file expanded so far: include-once
  std::map<fs::path, fs::path> standIns_;  // a withheld file's path -> the stand-in read in its place
  std::size_t versionLine_ = static_cast<std::size_t>(-1);
  bool merging_ = false;            // runAll, past the first file
  std::set<std::string> uniforms_;  // every uniform declaration line so far, trimmed in front
};

// "ERROR" -> "error", so every mapped line reads like a compiler diagnostic that editors parse.
std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool parseIndex(const std::string& digits, std::size_t& out) {
  if (digits.empty() || digits.size() > 9) return false;  // no overflow; logs never need more
  out = static_cast<std::size_t>(std::stoul(digits));
  return true;
}

}  // namespace

ShaderSource loadShaderSource(const std::string& path, const std::vector<std::string>& includeDirs) {
  return Expander(includeDirs).run(path);
}

ShaderSource loadShaderSources(const std::vector<std::string>& paths, const std::vector<std::string>& includeDirs) {
  if (paths.empty()) throw ShaderSourceError("loadShaderSources: no files");
  return Expander(includeDirs).runAll(paths);
}

std::string withDefines(const std::string& text, const std::vector<std::string>& defines) {
  if (defines.empty()) return text;
  const auto eol = text.find('\n');
  std::string head = text.substr(0, eol + 1), rest = text.substr(eol + 1);
  for (const auto& d : defines) head += "#define " + d + "\n";
  // Only add a #line if the preprocessor did not already put one right after #version.
  if (rest.rfind("#line", 0) != 0) head += "#line 2 0\n";
  return head + rest;
}

bool dependenciesChanged(const ShaderSource& source) {
  for (const FileStamp& dep : source.dependencies) {
    if (!dep.onDisk) continue;  // virtual text does not change under the program
    std::error_code ec;
    const fs::file_time_type now = fs::last_write_time(dep.path, ec);
    // A vanished file counts as a change: the reload then reports it instead of silently keeping
    // a program built from a file that no longer exists.
    if (ec || now != dep.writeTime) return true;
  }
  return false;
}

namespace {
// A hand-written scanner over one log line: std::regex recursed once per character and a 30,000
// character line (a long undeclared identifier) overflowed the stack.
class LineScanner {
 public:
  explicit LineScanner(std::string_view line) : s_(line) {}
  bool digits(std::string_view& out) {
    const std::size_t begin = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    out = s_.substr(begin, i_ - begin);
    return i_ > begin;
  }
  bool literal(std::string_view text) {
    if (s_.substr(i_, text.size()) != text) return false;
    i_ += text.size();
    return true;
  }
  std::string_view rest() const { return s_.substr(i_); }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

struct LogLocation {
  std::string_view source, line;
  std::string message;
};

// Mesa "0:12(5): msg", NVIDIA "0(12) : msg", AMD/Apple/glslang "ERROR: 0:12: msg".
bool parseLogLine(std::string_view text, LogLocation& out) {
  std::string_view column;
  LineScanner mesa(text);
  if (mesa.digits(out.source) && mesa.literal(":") && mesa.digits(out.line) && mesa.literal("(") &&
      mesa.digits(column) && mesa.literal("): ")) {
    out.message = std::string(mesa.rest());
    return true;
  }
  LineScanner nvidia(text);
  if (nvidia.digits(out.source) && nvidia.literal("(") && nvidia.digits(out.line) && nvidia.literal(") : ")) {
    out.message = std::string(nvidia.rest());
    return true;
  }
  for (const char* severity : {"ERROR", "WARNING", "NOTE", "INTERNAL ERROR", "UNIMPLEMENTED"}) {
    LineScanner prefixed(text);
    if (prefixed.literal(severity) && prefixed.literal(": ") && prefixed.digits(out.source) && prefixed.literal(":") &&
        prefixed.digits(out.line) && prefixed.literal(": ")) {
      out.message = lowercase(severity) + ": " + std::string(prefixed.rest());
      return true;
    }
  }
  return false;
}
}  // namespace

std::string mapCompileLog(const std::string& log, const std::vector<std::string>& files) {
  std::string out;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    const bool hasNewline = end != std::string::npos;
    if (!hasNewline) end = log.size();
    std::string_view line(log.data() + start, end - start);
    const bool carriage = !line.empty() && line.back() == '\r';
    if (carriage) line.remove_suffix(1);

    LogLocation at;
    std::size_t source = 0, lineNumber = 0;
    if (parseLogLine(line, at) && parseIndex(std::string(at.source), source) &&
        parseIndex(std::string(at.line), lineNumber) && source < files.size()) {
      out += files[source] + ":" + std::to_string(lineNumber) + ": " + at.message;
    } else {
      out += line;
    }
    if (carriage) out += '\r';
    if (hasNewline) out += '\n';
    start = end + 1;
  }
  return out;
}

namespace {
struct StageExtension {
  ShaderStage stage;
  std::string_view extension;
};
constexpr std::array<StageExtension, 6> kStageExtensions{{
    {ShaderStage::Vertex, ".vert"},
    {ShaderStage::Fragment, ".frag"},
    {ShaderStage::Geometry, ".geom"},
    {ShaderStage::TessControl, ".tesc"},
    {ShaderStage::TessEvaluation, ".tese"},
    {ShaderStage::Compute, ".comp"},
}};
}  // namespace

ShaderStage stageFromPath(const std::string& path) {
  const std::string extension = fs::path(path).extension().string();
  for (const StageExtension& entry : kStageExtensions) {
    if (entry.extension == extension) return entry.stage;
  }
  std::string valid;
  for (const StageExtension& entry : kStageExtensions) {
    valid += (valid.empty() ? "" : " ") + std::string(entry.extension);
  }
  throw ShaderSourceError("'" + path + "': unknown shader stage extension '" + extension + "' (expected one of " +
                          valid + ")");
}

std::string_view stageExtension(ShaderStage stage) {
  for (const StageExtension& entry : kStageExtensions) {
    if (entry.stage == stage) return entry.extension;
  }
  return {};
}

}  // namespace shadowlab

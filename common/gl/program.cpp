#include "gl/program.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>

#include <glm/gtc/type_ptr.hpp>

#include "core/glsl_es.hpp"
#include "core/paths.hpp"
#include "core/shader_files.hpp"
#include "gl/caps.hpp"
#include "gl/debug.hpp"

namespace shadowlab::gl {
namespace {

std::vector<Program*>& registry() {
  static std::vector<Program*> programs;
  return programs;
}

double now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

GLenum glStage(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return GL_VERTEX_SHADER;
    case ShaderStage::Fragment: return GL_FRAGMENT_SHADER;
    case ShaderStage::Geometry: return GL_GEOMETRY_SHADER;
    case ShaderStage::TessControl: return GL_TESS_CONTROL_SHADER;
    case ShaderStage::TessEvaluation: return GL_TESS_EVALUATION_SHADER;
    case ShaderStage::Compute: return GL_COMPUTE_SHADER;
  }
  return GL_VERTEX_SHADER;
}

// SHADOWLAB_SHADER_VARIANTS=FILE: each program compiled appends one line to FILE, once per process,
//   LABEL <tab> STAGE FILES (space-separated, relative to the shader root) [<tab> DEFINE]...
// so that shader_check --variants validates offline every variant a run asked for (tests/shaders.cmake).
// Appended (O_APPEND) in one write, the buffer sized to the line: runs in parallel never interleave
// lines. Plain stdio, so the GL layer keeps no POSIX-only call (the Windows build).
// Generated text (the GLSL exercise cases) has no file to check offline and is left out.
void recordVariant(std::string label, const std::vector<std::string>& files, const std::vector<std::string>& defines) {
  static const char* const path = std::getenv("SHADOWLAB_SHADER_VARIANTS");
  static std::set<std::string> recorded;  // GL thread only
  if (path == nullptr || *path == '\0') return;
  std::replace(label.begin(), label.end(), '\t', ' ');
  std::string line = label + '\t';
  for (const auto& f : files) {
    if (!std::filesystem::is_regular_file(shaderRoot() + "/" + f)) return;
    line += (&f == &files.front() ? "" : " ") + f;
  }
  for (const auto& d : defines) line += '\t' + d;
  line += '\n';
  if (!recorded.insert(line).second) return;
  std::FILE* file = std::fopen(path, "ab");
  bool written = file != nullptr && std::setvbuf(file, nullptr, _IOFBF, line.size() + 1) == 0 &&
                 std::fwrite(line.data(), 1, line.size(), file) == line.size();
  if (file != nullptr) written = std::fclose(file) == 0 && written;
  if (!written) std::cerr << "SHADOWLAB_SHADER_VARIANTS: cannot append to '" << path << "'\n";
}

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::max(length, 1), '\0');
  isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(std::char_traits<char>::length(log.c_str()));
  return log;
}

// Driver logs end in a newline: one error is then one line where it is printed.
std::string trimEnd(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

const std::vector<Program*>& livePrograms() { return registry(); }

std::vector<std::string> shaderErrors(bool requiredOnly) {
  std::vector<std::string> errors;
  for (const Program* p : livePrograms())
    if (!p->error().empty() && (!requiredOnly || p->required())) errors.push_back(p->error());
  return errors;
}

bool programsReady() {
  for (const Program* p : livePrograms())
    if (p->required() && !p->valid() && !p->building()) return false;
  return true;
}

namespace {
bool g_async = false;
}

std::vector<std::string> modeDefines(const std::vector<ShaderMode>& modes) {
  std::vector<std::string> defines;
  for (const ShaderMode& m : modes) defines.push_back(std::string(m.define) + " " + std::to_string(m.value));
  return defines;
}

void setModeUniforms(const Program& program, const std::vector<ShaderMode>& modes) {
  for (const ShaderMode& m : modes) program.set(m.uniform, m.value);
}

void setAsyncCompile(bool on) {
  g_async = on && caps().parallelShaderCompile;
  if (g_async) glMaxShaderCompilerThreadsKHR(0xFFFFFFFFu);  // as many threads as the driver likes
}

bool asyncCompile() { return g_async; }

Program::Program(std::string label, std::vector<std::string> files, std::vector<std::string> defines)
    : label_(std::move(label)), files_(std::move(files)), defines_(std::move(defines)) {}

Program::~Program() {
  auto& live = registry();
  live.erase(std::remove(live.begin(), live.end(), this), live.end());
}

// The files to compile. SHADOWLAB_FLOOR_SHADER=1 (the benchmark's floor) swaps every fragment
// stage for shaders/common/floor.frag: the same frame with a trivial fragment shader (but for the
// data passes marked keepUnderFloor()).
std::vector<std::string> Program::stageFiles() const {
  static const bool floor =
      std::getenv("SHADOWLAB_FLOOR_SHADER") && std::string(std::getenv("SHADOWLAB_FLOOR_SHADER")) == "1";
  if (!floor || keepUnderFloor_) return files_;
  std::vector<std::string> files;
  bool fragment = false;
  for (const auto& f : files_) {
    if (stageFromPath(f) != ShaderStage::Fragment) files.push_back(f);
    else if (!fragment) files.push_back("common/floor.frag");
    fragment = fragment || stageFromPath(f) == ShaderStage::Fragment;
  }
  return files;
}

// The shaders to compile, each a list of files: one file each, or in OpenGL ES (one shader per
// stage) each stage's files as one source (core/shader_source's loadShaderSources).
std::vector<std::vector<std::string>> Program::compileUnits() const {
  std::vector<std::vector<std::string>> units;
  for (const std::string& file : stageFiles()) {
    auto same = std::find_if(units.begin(), units.end(),
                             [&](const auto& u) { return stageFromPath(u.front()) == stageFromPath(file); });
    if (caps().gles && same != units.end()) same->push_back(file);
    else units.push_back({file});
  }
  return units;
}

// Compiles every stage and links, without waiting for the results: with
// GL_KHR_parallel_shader_compile the driver does the work on its own threads.
void Program::start() {
  auto& live = registry();
  if (std::find(live.begin(), live.end(), this) == live.end()) live.push_back(this);
  pending_ = std::make_unique<Pending>();
  const std::string root = shaderRoot();
  recordVariant(label_, stageFiles(), defines_);
  try {
    for (const std::vector<std::string>& unit : compileUnits()) {
      std::vector<std::string> paths;
      for (const std::string& file : unit) paths.push_back(root + "/" + file);
      pending_->sources.push_back(paths.size() == 1 ? loadShaderSource(paths[0], {root})
                                                    : loadShaderSources(paths, {root}));
      const std::string& file = unit.front();
      std::string text = withDefines(pending_->sources.back().text, defines_);
      // What the context lacks, for the shaders' fallbacks: no border clamp (test the range), no
      // gl_ClipDistance (interpolate the distances and discard), no depth clamp (flatten in the shader).
      if (!caps().clampToBorder) text = withDefines(text, {"SHADOWLAB_NO_BORDER_CLAMP"});
      if (!caps().clipDistance) text = withDefines(text, {"SHADOWLAB_NO_CLIP_DISTANCE"});
      if (!caps().depthClamp) text = withDefines(text, {"SHADOWLAB_NO_DEPTH_CLAMP"});
      if (caps().gles) text = toGlslEs(text);  // WebGL2: GLSL ES 3.00 (core/glsl_es.hpp)
      ShaderHandle shader(glCreateShader(glStage(stageFromPath(file))));
      const char* src = text.c_str();
      glShaderSource(shader.id(), 1, &src, nullptr);
      glCompileShader(shader.id());
      gl::label(GL_SHADER, shader.id(), label_ + ":" + file);
      pending_->shaders.push_back(std::move(shader));
    }
  } catch (const ShaderSourceError& e) {
    pending_->error = label_ + ": " + e.what();
    return;
  }
  pending_->program = ProgramHandle(glCreateProgram());
  for (const auto& s : pending_->shaders) glAttachShader(pending_->program.id(), s.id());
  glLinkProgram(pending_->program.id());
}

// Takes the results: the new program, or the error (file:line) with the last good program kept.
bool Program::finish() {
  Pending p = std::move(*pending_);
  pending_.reset();
  // Keep the sources read so far, also on failure: a fix to any of them triggers the next reload.
  // (A file that could not be read at all leaves the list short, and the next poll tries again.)
  sources_ = std::move(p.sources);
  if (!p.error.empty()) {
    error_ = trimEnd(p.error);
    return false;
  }
  for (std::size_t i = 0; i < p.shaders.size(); ++i) {
    GLint ok = 0;
    glGetShaderiv(p.shaders[i].id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      error_ = trimEnd(label_ + ": " + mapCompileLog(infoLog(p.shaders[i].id(), false), sources_[i].files));
      return false;
    }
  }
  GLint ok = 0;
  glGetProgramiv(p.program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    error_ = trimEnd(label_ + ": link failed: " + infoLog(p.program.id(), true));
    return false;
  }
  gl::label(GL_PROGRAM, p.program.id(), label_);
  program_ = std::move(p.program);
  standIns_.clear();
  // The sources name the stand-in read (exercises.glsl), not the withheld file it stood in for.
  const std::vector<std::string> replaced = withheldReplaced();
  const std::filesystem::path root = replaced.empty() ? "" : std::filesystem::weakly_canonical(shaderRoot());
  for (const std::string& rel : replaced) {
    const std::string standIn = (root / withheldStandIn(rel)).string();
    if (std::any_of(sources_.begin(), sources_.end(), [&](const ShaderSource& source) {
          return std::find(source.files.begin(), source.files.end(), standIn) != source.files.end();
        }))
      standIns_.push_back(rel);
  }
  locations_.clear();
  error_.clear();
  return true;
}

void Program::noteStandInsDrawn() const { noteWithheldDrawn(standIns_); }

bool Program::build() {
  start();
  return finish();
}

void Program::buildAsync() {
  if (!asyncCompile()) {
    build();
    return;
  }
  start();
}

bool Program::ready() {
  if (!pending_) return true;
  if (pending_->program) {
    GLint done = GL_FALSE;
    glGetProgramiv(pending_->program.id(), GL_COMPLETION_STATUS_KHR, &done);
    if (!done) return false;
  }
  finish();
  return true;
}

bool Program::reloadIfChanged() {
  const double t = now();
  if (t - lastPoll_ < 0.25) return false;
  lastPoll_ = t;
  const bool changed =
      sources_.size() < compileUnits().size() ||
      std::any_of(sources_.begin(), sources_.end(), [](const ShaderSource& s) { return dependenciesChanged(s); });
  if (!changed) return false;
  sources_.clear();
  return build();
}

Program& ProgramVariants::variant(const std::vector<std::string>& defines, const std::vector<std::string>& extraFiles,
                                  bool async) {
  std::string key;
  for (const auto& f : extraFiles) key += f + ';';
  key += '|';
  for (const auto& d : defines) key += d + ';';
  auto it = programs_.find(key);
  if (it != programs_.end()) return *it->second;
  std::vector<std::string> files = files_;
  files.insert(files.end(), extraFiles.begin(), extraFiles.end());
  std::string label = label_;
  for (const auto& f : extraFiles) label += " + " + f;
  for (const auto& d : defines) label += " [" + d + "]";
  std::vector<std::string> all = baseDefines_;
  all.insert(all.end(), defines.begin(), defines.end());
  auto program = std::make_unique<Program>(label, std::move(files), std::move(all));
  async ? program->buildAsync() : void(program->build());
  return *programs_.emplace(key, std::move(program)).first->second;
}

Program& ProgramVariants::get(const std::vector<std::string>& defines, const std::vector<std::string>& extraFiles,
                              bool wait) {
  // SHADOWLAB_SPECIALISE=0: every program generic, for measuring what specialisation buys.
  static const bool specialise =
      !std::getenv("SHADOWLAB_SPECIALISE") || std::string(std::getenv("SHADOWLAB_SPECIALISE")) != "0";
  if (!specialise) return variant({}, extraFiles, false);
  if (!asyncCompile() || defines.empty() || wait) return variant(defines, extraFiles, false);
  // Interactive: the specialised program compiles on the driver's threads; until it is ready the
  // generic one (the same shaders without the defines, driven by uniforms) draws the same picture.
  Program& generic = variant({}, extraFiles, false);
  Program& specialised = variant(defines, extraFiles, true);
  return specialised.ready() ? specialised : generic;
}

GLint Program::location(const char* name) const {
  if (!program_) return -1;  // never built, or its first build failed: nothing to set
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(program_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

// A program that never built has nothing bound to set (GL would report the call as an error).
void Program::set(const char* n, float v) const {
  if (program_) glUniform1f(location(n), v);
}
void Program::set(const char* n, int v) const {
  if (program_) glUniform1i(location(n), v);
}
void Program::set(const char* n, const glm::vec2& v) const {
  if (program_) glUniform2fv(location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
  if (program_) glUniform2iv(location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
  if (program_) glUniform3fv(location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
  if (program_) glUniform4fv(location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat3& v) const {
  if (program_) glUniformMatrix3fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  if (program_) glUniformMatrix4fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace shadowlab::gl

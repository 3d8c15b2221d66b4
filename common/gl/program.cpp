#include "gl/program.hpp"

#include <algorithm>
#include <chrono>

#include <glm/gtc/type_ptr.hpp>

#include "core/paths.hpp"
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

// Defines go right after #version, followed by a #line so logs keep the file's own numbering.
std::string withDefines(const std::string& text, const std::vector<std::string>& defines) {
  if (defines.empty()) return text;
  const auto eol = text.find('\n');
  std::string head = text.substr(0, eol + 1), rest = text.substr(eol + 1);
  for (const auto& d : defines) head += "#define " + d + "\n";
  // Only add a #line if the preprocessor did not already put one right after #version.
  if (rest.rfind("#line", 0) != 0) head += "#line 2 0\n";
  return head + rest;
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

}  // namespace

const std::vector<Program*>& livePrograms() { return registry(); }

Program::Program(std::string label, std::vector<std::string> files, std::vector<std::string> defines)
    : label_(std::move(label)), files_(std::move(files)), defines_(std::move(defines)) {}

Program::~Program() {
  auto& live = registry();
  live.erase(std::remove(live.begin(), live.end(), this), live.end());
}

bool Program::build() {
  auto& live = registry();
  if (std::find(live.begin(), live.end(), this) == live.end()) live.push_back(this);
  std::vector<ShaderSource> sources;
  std::vector<ShaderHandle> shaders;
  const std::string root = shaderRoot();
  try {
    for (const auto& file : files_) {
      sources.push_back(loadShaderSource(root + "/" + file, {root}));
      const std::string text = withDefines(sources.back().text, defines_);
      ShaderHandle shader(glCreateShader(glStage(stageFromPath(file))));
      const char* src = text.c_str();
      glShaderSource(shader.id(), 1, &src, nullptr);
      glCompileShader(shader.id());
      GLint ok = 0;
      glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
      if (!ok) throw ShaderSourceError(mapCompileLog(infoLog(shader.id(), false), sources.back().files));
      gl::label(GL_SHADER, shader.id(), label_ + ":" + file);
      shaders.push_back(std::move(shader));
    }
  } catch (const ShaderSourceError& e) {
    // Keep the sources read so far: a fix to any of them triggers the next reload. (A file that
    // could not be read at all leaves the list short, and the next poll simply tries again.)
    sources_ = std::move(sources);
    error_ = label_ + ": " + e.what();
    return false;
  }
  ProgramHandle program(glCreateProgram());
  for (const auto& s : shaders) glAttachShader(program.id(), s.id());
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  sources_ = std::move(sources);
  if (!ok) {
    error_ = label_ + ": link failed: " + infoLog(program.id(), true);
    return false;
  }
  gl::label(GL_PROGRAM, program.id(), label_);
  program_ = std::move(program);
  locations_.clear();
  error_.clear();
  return true;
}

bool Program::reloadIfChanged() {
  const double t = now();
  if (t - lastPoll_ < 0.25) return false;
  lastPoll_ = t;
  const bool changed =
      sources_.size() < files_.size() ||
      std::any_of(sources_.begin(), sources_.end(), [](const ShaderSource& s) { return dependenciesChanged(s); });
  if (!changed) return false;
  sources_.clear();
  return build();
}

Program& ProgramVariants::get(const std::vector<std::string>& defines, const std::vector<std::string>& extraFiles) {
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
  auto program = std::make_unique<Program>(label, std::move(files), defines);
  program->build();
  return *programs_.emplace(key, std::move(program)).first->second;
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(program_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const char* n, float v) const { glUniform1f(location(n), v); }
void Program::set(const char* n, int v) const { glUniform1i(location(n), v); }
void Program::set(const char* n, const glm::vec2& v) const { glUniform2fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec3& v) const { glUniform3fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec4& v) const { glUniform4fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::mat3& v) const {
  glUniformMatrix3fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  glUniformMatrix4fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace shadowlab::gl

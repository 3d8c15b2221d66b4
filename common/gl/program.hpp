#pragma once
// Shader programs loaded from the source tree (shaders/, root fixed at configure time, SHADOWLAB_ROOT
// overrides), with #include and #line (core/shader_source), and hot reload: when a file changes the
// program is rebuilt; if that fails the last good program stays in use and error() says why, with
// file:line, for the UI header.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "core/shader_source.hpp"
#include "gl/objects.hpp"

namespace shadowlab::gl {

class Program {
 public:
  Program() = default;
  // `files` are relative to the shader root, e.g. {"01_lighting/scene.vert", "01_lighting/scene.frag"};
  // the stage comes from the extension. `defines` are inserted after #version ("#define NAME 1").
  Program(std::string label, std::vector<std::string> files, std::vector<std::string> defines = {});
  ~Program();
  // Registered by address for the UI's error list and reload-all: not copyable or movable.
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  // Compiles and links. On failure the previous program (if any) is kept and error() is set;
  // returns whether the new build succeeded.
  bool build();
  // The same without waiting, where the driver compiles in parallel (asyncCompile()); ready()
  // says when the result is in (and takes it). Without parallel compilation: build().
  void buildAsync();
  bool ready();
  // A first build still compiling: nothing to draw with yet, and no error either.
  bool building() const { return pending_ && !program_; }
  // Polls the files (cheaply, at most every 250 ms) and rebuilds when one changed.
  bool reloadIfChanged();
  bool valid() const { return bool(program_); }
  const std::string& error() const { return error_; }
  const std::string& label() const { return label_; }
  // Whether this program's failure stops the frame (and a headless run): always, unless
  // `required` says otherwise now. A GLSL exercise's student build (app/exercise_program.hpp) is
  // required only while impl=student, so a student file that does not compile shows its error
  // without stopping the reference.
  void setRequired(std::function<bool()> required) { required_ = std::move(required); }
  bool required() const { return !required_ || required_(); }
  GLuint id() const { return program_.id(); }
  // A pass whose fragment shader computes data later passes index by (the hybrid map's counts and
  // record offsets), not shading: the benchmark's floor (SHADOWLAB_FLOOR_SHADER=1) keeps its
  // shader, since a trivial one there gives garbage sizes and no frame to measure. Before build().
  void keepUnderFloor() { keepUnderFloor_ = true; }

  void use() const {
    glUseProgram(program_.id());
    if (!standIns_.empty()) noteStandInsDrawn();
  }
  GLint location(const char* name) const;  // cached; -1 when the uniform is unused
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, bool v) const { set(name, int(v)); }
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::mat3& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  struct Pending {
    std::vector<ShaderSource> sources;
    std::vector<ShaderHandle> shaders;
    ProgramHandle program;
    std::string error;  // a source that could not be read or expanded
  };
  void start();
  bool finish();
  std::vector<std::string> stageFiles() const;
  std::vector<std::vector<std::string>> compileUnits() const;

  std::string label_;
  std::vector<std::string> files_;
  std::vector<std::string> defines_;
  std::vector<ShaderSource> sources_;
  // The withheld files (core/shader_files.hpp) this build read from their stand-ins: the student
  // handout and the browser. use() notes them, so the lesson says whose GLSL draws only while it does.
  std::vector<std::string> standIns_;
  void noteStandInsDrawn() const;
  std::unique_ptr<Pending> pending_;
  ProgramHandle program_;
  std::string error_;
  std::function<bool()> required_;
  bool keepUnderFloor_ = false;
  double lastPoll_ = 0;
  mutable std::unordered_map<std::string, GLint> locations_;
};

// One program per set of #defines (and extra files, such as the fragment shader a shadow technique
// links in), built on first use and kept: a shader specialised for the features in use, since a
// software renderer pays for a feature a uniform switches off. Each variant hot-reloads on its own.
class ProgramVariants {
 public:
  // `baseDefines` go into every variant (a GLSL exercise's student build: SHADOWLAB_STUDENT_GLSL).
  ProgramVariants(std::string label, std::vector<std::string> files, std::vector<std::string> baseDefines = {})
      : label_(std::move(label)), files_(std::move(files)), baseDefines_(std::move(baseDefines)) {}
  // The program for `defines`. Compiled asynchronously when asyncCompile() is on (interactive
  // windows): until it is ready this returns the generic variant (no defines), so switching a
  // feature never stalls a frame. Headless runs build synchronously (deterministic frames).
  // `wait`: build it now even in a window (a measured frame must be drawn by the variant it asks for).
  Program& get(const std::vector<std::string>& defines, const std::vector<std::string>& extraFiles = {},
               bool wait = false);
  std::size_t size() const { return programs_.size(); }

 private:
  Program& variant(const std::vector<std::string>& defines, const std::vector<std::string>& extraFiles, bool async);
  std::string label_;
  std::vector<std::string> files_, baseDefines_;
  std::map<std::string, std::unique_ptr<Program>> programs_;
};

// A mode a shader takes both ways: as a constant of its specialised variant (#define NAME value) and
// as the uniform its generic build reads, which draws while a window compiles that variant.
struct ShaderMode {
  const char* define;   // "VIEW"
  const char* uniform;  // "uView"
  int value;
};
std::vector<std::string> modeDefines(const std::vector<ShaderMode>& modes);          // {"VIEW 2", ...}
void setModeUniforms(const Program& program, const std::vector<ShaderMode>& modes);  // in use

// Parallel shader compilation (GL_KHR_parallel_shader_compile), where the driver has it: the app
// turns it on for interactive windows, off for headless runs whose frames must be reproducible.
void setAsyncCompile(bool on);
bool asyncCompile();

// Every live Program, so the framework can list shader errors in the header and reload all.
const std::vector<Program*>& livePrograms();
// Every live program's error (the header shows them), or only those of programs in use (fatal
// headless).
std::vector<std::string> shaderErrors(bool requiredOnly = false);
// Every program in use is built (none still compiling, none failed).
bool programsReady();

}  // namespace shadowlab::gl

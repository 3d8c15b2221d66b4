#pragma once
// GL errors are never ignored. With KHR_debug the driver calls us for every message; without it
// (a 4.1 context on macOS) checkErrors() polls glGetError at the end of every frame, and in strict
// mode also at both ends of every timed pass, so an error names the pass that made it. Errors are
// counted; in strict mode (tests: --strict-gl) the app exits with code 3 when any was seen.
#include <string>
#include <vector>

namespace shadowlab::gl {

// After the context is current. `strict`: without a debug callback, also poll where every timed
// pass begins and ends (GpuTimers), so an error names its pass.
void installDebugOutput(bool strict = false);
void checkErrors(const char* where);  // glGetError poll; records any error with `where`
int errorCount();                     // GL debug messages of type error, and polled errors
// GpuTimers at both ends of a pass: a glGetError poll naming the pass, when installed strict.
void checkPassErrors(const char* when, const std::string& pass);
const std::vector<std::string>& errorMessages();  // the first few, for the report at exit
const std::string& lastErrorMessage();

// Gives a GL object a debug label (no-op without KHR_debug). `identifier`: GL_BUFFER, GL_TEXTURE...
void label(unsigned identifier, unsigned name, const std::string& text);

// Groups the calls of a pass in debuggers (RenderDoc, apitrace) when KHR_debug is there.
class DebugGroup {
 public:
  explicit DebugGroup(const char* name);
  ~DebugGroup();
  DebugGroup(const DebugGroup&) = delete;
  DebugGroup& operator=(const DebugGroup&) = delete;

 private:
  bool pushed_ = false;
};

}  // namespace shadowlab::gl

#include "gl/debug.hpp"

#include <algorithm>
#include <cstdio>

#include "gl/caps.hpp"
#include "gl/gl.hpp"

namespace shadowlab::gl {
namespace {
int g_errors = 0;
bool g_callback = false;  // the driver reports errors itself; glGetError is then only drained
bool g_pollPasses = false;
std::vector<std::string> g_messages;
std::string g_last;

void record(const std::string& message) {
  ++g_errors;
  if (g_messages.size() < 16) g_messages.push_back(message);
  g_last = message;
  std::fprintf(stderr, "GL error: %s\n", message.c_str());
}

void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length, const GLchar* message,
                          const void*) {
  // A shader that fails to compile is reported by its Program (file:line, last good program kept),
  // not as a GL error nor printed again unmapped: Mesa also sends the compiler's log through here.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  if (type == GL_DEBUG_TYPE_ERROR) {
    record(std::string(message, length > 0 ? size_t(length) : std::char_traits<char>::length(message)));
  } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
    std::fprintf(stderr, "GL: %.*s\n", int(length), message);
  }
}

const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
  }
}
}  // namespace

void installDebugOutput(bool strict) {
  g_pollPasses = strict && !caps().khrDebug;
  if (!caps().khrDebug) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // errors reported at the call that caused them
  glDebugMessageCallback(onMessage, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
  g_callback = true;
}

void checkErrors(const char* where) {
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    if (!g_callback) record(std::string(errorName(e)) + " at " + where);
}

void checkPassErrors(const char* when, const std::string& pass) {
  if (g_pollPasses && !g_callback) checkErrors((std::string(when) + " pass '" + pass + "'").c_str());
}

int errorCount() { return g_errors; }
const std::vector<std::string>& errorMessages() { return g_messages; }
const std::string& lastErrorMessage() { return g_last; }

// A label longer than GL_MAX_LABEL_LENGTH - 1 is GL_INVALID_VALUE (a program variant's label
// carries its defines, which can pass the 256 the spec guarantees): such a label is cut to fit.
void label(unsigned identifier, unsigned name, const std::string& text) {
  if (!caps().khrDebug || name == 0) return;
  static const GLint maxLength = [] {
    GLint n = 256;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &n);
    return n;
  }();
  const std::size_t length = std::min(text.size(), std::size_t(std::max(maxLength - 1, 0)));
  glObjectLabel(identifier, name, GLsizei(length), text.c_str());
}

DebugGroup::DebugGroup(const char* name) {
  if (caps().khrDebug) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
    pushed_ = true;
  }
}
DebugGroup::~DebugGroup() {
  if (pushed_) glPopDebugGroup();
}

}  // namespace shadowlab::gl

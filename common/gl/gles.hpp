#pragma once
// OpenGL 4.1 names that OpenGL ES 3.0 (WebGL2) lacks, for the browser build only (gl/gl.hpp
// includes this under __EMSCRIPTEN__). The enums keep desktop code compiling; every function here
// is reached only where gl::caps() says the feature exists, and otherwise throws naming the call,
// so a missing caps check is a clear error in the page, never a silent wrong picture.
#include <emscripten/emscripten.h>

#include <stdexcept>
#include <string>

namespace shadowlab::gl::es {
[[noreturn]] inline void unavailable(const char* call) {
  throw std::logic_error(std::string(call) + " is not in WebGL2: the caller must check gl::caps() first");
}
}  // namespace shadowlab::gl::es

// ---- enums (values from the OpenGL 4.6 core registry) ------------------------------------------
#define GL_DEPTH_CLAMP 0x864F
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_TEXTURE_LOD_BIAS 0x8501
#define GL_CLIP_DISTANCE0 0x3000
#define GL_LINE 0x1B01
#define GL_FILL 0x1B02
#define GL_LOWER_LEFT 0x8CA1
#define GL_ZERO_TO_ONE 0x935F
#define GL_TIMESTAMP 0x8E28
#define GL_SAMPLES_PASSED 0x8914
#define GL_RGBA16 0x805B
#define GL_GEOMETRY_SHADER 0x8DD9
#define GL_TESS_CONTROL_SHADER 0x8E88
#define GL_TESS_EVALUATION_SHADER 0x8E87
#define GL_COMPUTE_SHADER 0x91B9
#define GL_TRIANGLES_ADJACENCY 0x000C
#define GL_DEBUG_OUTPUT 0x92E0
#define GL_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define GL_DEBUG_SEVERITY_HIGH 0x9146
#define GL_DEBUG_SEVERITY_MEDIUM 0x9147
#define GL_DEBUG_SEVERITY_NOTIFICATION 0x826B
#define GL_DEBUG_SOURCE_APPLICATION 0x824A
#define GL_DEBUG_SOURCE_SHADER_COMPILER 0x8248
#define GL_DEBUG_TYPE_ERROR 0x824C
#define GL_MAX_LABEL_LENGTH 0x82E8
#define GL_BUFFER 0x82E0
#define GL_SHADER 0x82E1
#define GL_PROGRAM 0x82E2
#define GL_VERTEX_ARRAY 0x8074

#define GLAPIENTRY GL_APIENTRY
typedef void (*GLDEBUGPROC)(GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar*, const void*);

// ---- functions ---------------------------------------------------------------------------------
// ES has glDrawBuffers only: one buffer (or none) is the same call with a list of one.
inline void glDrawBuffer(GLenum buffer) { glDrawBuffers(1, &buffer); }
inline void glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count, GLsizei n) {
  for (GLsizei i = 0; i < n; ++i) glDrawArrays(mode, first[i], count[i]);
}
// WEBGL_polygon_mode (the context enables it where the browser has it: gl::caps().polygonMode), the
// same enums as desktop GL's; without it, the call is a mistake the caps should have caught.
inline void glPolygonMode(GLenum face, GLenum mode) {
  if (!EM_ASM_INT(
          {
            var e = GLctx.getExtension('WEBGL_polygon_mode');
            if (!e) return 0;
            e.polygonModeWEBGL($0, $1);
            return 1;
          },
          face, mode))
    shadowlab::gl::es::unavailable("glPolygonMode (no WEBGL_polygon_mode)");
}
inline void glGetTexImage(GLenum, GLint, GLenum, GLenum, void*) { shadowlab::gl::es::unavailable("glGetTexImage"); }
inline void glQueryCounter(GLuint, GLenum) { shadowlab::gl::es::unavailable("glQueryCounter"); }
inline void glGetQueryObjectui64v(GLuint, GLenum, GLuint64*) {
  shadowlab::gl::es::unavailable("glGetQueryObjectui64v");
}
inline void glGetQueryObjectiv(GLuint, GLenum, GLint*) { shadowlab::gl::es::unavailable("glGetQueryObjectiv"); }
inline void glClipControl(GLenum, GLenum) { shadowlab::gl::es::unavailable("glClipControl"); }
inline void glColorMaski(GLuint, GLboolean, GLboolean, GLboolean, GLboolean) {
  shadowlab::gl::es::unavailable("glColorMaski");
}
inline void glDisablei(GLenum, GLuint) { shadowlab::gl::es::unavailable("glDisablei"); }
inline void glObjectLabel(GLenum, GLuint, GLsizei, const GLchar*) {}  // labels: a debugging aid only
inline void glPushDebugGroup(GLenum, GLuint, GLsizei, const GLchar*) {}
inline void glPopDebugGroup() {}
inline void glDebugMessageCallback(GLDEBUGPROC, const void*) {
  shadowlab::gl::es::unavailable("glDebugMessageCallback");
}
inline void glDebugMessageControl(GLenum, GLenum, GLenum, GLsizei, const GLuint*, GLboolean) {
  shadowlab::gl::es::unavailable("glDebugMessageControl");
}
inline void glMaxShaderCompilerThreadsKHR(GLuint) {}

#include "gl/caps.hpp"

#include <cstdlib>
#include <algorithm>

#include "gl/gl.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace shadowlab::gl {
namespace {
Caps g_caps;
bool g_detected = false;

// Whether SHADOWLAB_GL_HIDE names the extension: a feature the driver has is then treated as
// absent, so its fallback runs here (core features are hidden by the ARB extension that brought
// them: GL_ARB_geometry_shader4, GL_ARB_depth_clamp, GL_ARB_texture_border_clamp; those core
// since 3.0 that WebGL2 lacks by the name WebGL2 gives them: GL_EXT_color_buffer_float,
// GL_OES_texture_float_linear, GL_EXT_clip_cull_distance, GL_EXT_texture_norm16; glGetTexImage by its own name).
bool hidden(const std::string& name) {
  const char* list = std::getenv("SHADOWLAB_GL_HIDE");
  return list && (std::string(",") + list + ",").find("," + name + ",") != std::string::npos;
}

// An extension the driver offers and SHADOWLAB_GL_HIDE does not name.
bool has(const char* extension) {
  const std::string name = extension;
  if (hidden(name)) return false;
#ifdef __EMSCRIPTEN__  // WebGL2's extensions, as emscripten names them (GL_EXT_color_buffer_float)
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
    if (const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))); e && name == e)
      return true;
  return false;
#else
  return epoxy_has_gl_extension(extension);
#endif
}

std::string str(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}
}  // namespace

const Caps& caps() {
  if (g_detected) return g_caps;
  Caps c;
  glGetIntegerv(GL_MAJOR_VERSION, &c.major);
  glGetIntegerv(GL_MINOR_VERSION, &c.minor);
  c.vendor = str(GL_VENDOR);
  c.renderer = str(GL_RENDERER);
  c.version = str(GL_VERSION);
  c.glsl = str(GL_SHADING_LANGUAGE_VERSION);
#ifdef __EMSCRIPTEN__
  c.gles = true;
  // WebGL masks the renderer ("WebKit WebGL"); the page may still name it (WEBGL_debug_renderer_info),
  // and the frame budget needs to know a software one (Chromium's SwiftShader) as natively llvmpipe.
  if (char* unmasked = reinterpret_cast<char*>(EM_ASM_INT({
        var e = GLctx.getExtension('WEBGL_debug_renderer_info');
        if (!e) return 0;
        var s = String(GLctx.getParameter(e.UNMASKED_RENDERER_WEBGL));
        var p = _malloc(lengthBytesUTF8(s) + 1);
        stringToUTF8(s, p, lengthBytesUTF8(s) + 1);
        return p;
      }))) {
    if (*unmasked) c.renderer = unmasked;
    std::free(unmasked);
  }
  c.major = 3, c.minor = 0;  // WebGL2 is ES 3.0: every desktop version test below is false, as it should be
  c.depthClamp = has("GL_EXT_depth_clamp");
  c.floatColorBuffers = has("GL_EXT_color_buffer_float");
  c.floatLinear = has("GL_OES_texture_float_linear");
  c.polygonMode = has("GL_WEBGL_polygon_mode");
  c.norm16 = has("GL_EXT_texture_norm16");
#else
  c.polygonMode = true;                                        // core since 1.0
  c.getTexImage = !hidden("glGetTexImage");                    // core since 1.0
  c.floatColorBuffers = !hidden("GL_EXT_color_buffer_float");  // core since 3.0
  c.floatLinear = !hidden("GL_OES_texture_float_linear");      // core since 3.0
  c.clipDistance = !hidden("GL_EXT_clip_cull_distance");       // core since 3.0
  c.norm16 = !hidden("GL_EXT_texture_norm16");                 // core since 3.0
  c.depthClamp = !hidden("GL_ARB_depth_clamp");                // core since 3.2
  c.geometryShaders = !hidden("GL_ARB_geometry_shader4");      // core since 3.2
  c.clampToBorder = !hidden("GL_ARB_texture_border_clamp");    // core since 1.3
#endif
  c.khrDebug = !c.gles && (c.atLeast(4, 3) || has("GL_KHR_debug"));
  c.clipControl = c.atLeast(4, 5) || has("GL_ARB_clip_control");
  c.anisotropic =
      c.atLeast(4, 6) || has("GL_EXT_texture_filter_anisotropic") || has("GL_ARB_texture_filter_anisotropic");
  if (c.anisotropic) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &c.maxAnisotropy);
  c.computeShaders = c.atLeast(4, 3) || has("GL_ARB_compute_shader");
  c.directStateAccess = c.atLeast(4, 5) || has("GL_ARB_direct_state_access");
  c.timerQuery = c.atLeast(3, 3) || has("GL_ARB_timer_query");
  // The extension itself, not the version: a #version 410 shader enables it by name.
  c.derivativeControl = has("GL_ARB_derivative_control");
  c.parallelShaderCompile = has("GL_KHR_parallel_shader_compile");
  c.softwareRenderer = c.renderer.find("llvmpipe") != std::string::npos ||
                       c.renderer.find("softpipe") != std::string::npos ||
                       c.renderer.find("SwiftShader") != std::string::npos;
  if (const char* s = std::getenv("SHADOWLAB_SOFTWARE_RENDERER")) c.softwareRenderer = std::string(s) == "1";
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &c.maxTextureSize);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &c.maxRenderbufferSize);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, c.maxViewport);
  g_caps = c;
  g_detected = true;
  return g_caps;
}

void resetCaps() { g_detected = false; }

std::string Caps::summary() const {
  return renderer + " | GL " + std::to_string(major) + "." + std::to_string(minor) + " (" + version + ")";
}

std::string framebufferSizeProblem(int width, int height) {
  const Caps& c = caps();
  const int maxWidth = std::min({c.maxTextureSize, c.maxRenderbufferSize, c.maxViewport[0]});
  const int maxHeight = std::min({c.maxTextureSize, c.maxRenderbufferSize, c.maxViewport[1]});
  if (width <= maxWidth && height <= maxHeight) return "";
  return "a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer exceeds this OpenGL's limits (" +
         c.renderer + "): at most " + std::to_string(maxWidth) + "x" + std::to_string(maxHeight) +
         " (GL_MAX_TEXTURE_SIZE " + std::to_string(c.maxTextureSize) + ", GL_MAX_RENDERBUFFER_SIZE " +
         std::to_string(c.maxRenderbufferSize) + ", GL_MAX_VIEWPORT_DIMS " + std::to_string(c.maxViewport[0]) + "x" +
         std::to_string(c.maxViewport[1]) + ")";
}

std::string textureSizeProblem(int width, int height) {
  const int limit = caps().maxTextureSize;
  if (width <= limit && height <= limit) return "";
  return std::to_string(width) + "x" + std::to_string(height) + " is larger than this OpenGL's GL_MAX_TEXTURE_SIZE " +
         std::to_string(limit) + " (" + caps().renderer + ")";
}

}  // namespace shadowlab::gl

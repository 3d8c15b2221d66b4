#include "gl/caps.hpp"

#include <cstdlib>
#include <algorithm>

#include "gl/gl.hpp"

namespace shadowlab::gl {
namespace {
Caps g_caps;
bool g_detected = false;

// An extension the driver offers and SHADOWLAB_GL_HIDE does not name.
bool has(const char* extension) {
  if (const char* hidden = std::getenv("SHADOWLAB_GL_HIDE")) {
    const std::string list = std::string(",") + hidden + ",";
    const std::string name = std::string(",") + extension + ",";
    if (list.find(name) != std::string::npos) return false;
  }
  return epoxy_has_gl_extension(extension);
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
  c.khrDebug = c.atLeast(4, 3) || has("GL_KHR_debug");
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
  c.softwareRenderer =
      c.renderer.find("llvmpipe") != std::string::npos || c.renderer.find("softpipe") != std::string::npos;
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

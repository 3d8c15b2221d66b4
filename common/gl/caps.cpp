#include "gl/caps.hpp"

#include <cstdlib>

#include "gl/gl.hpp"

namespace shadowlab::gl {
namespace {
Caps g_caps;
bool g_detected = false;

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
  c.khrDebug = c.atLeast(4, 3) || epoxy_has_gl_extension("GL_KHR_debug");
  c.clipControl = c.atLeast(4, 5) || epoxy_has_gl_extension("GL_ARB_clip_control");
  c.anisotropic = c.atLeast(4, 6) || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
                  epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic");
  if (c.anisotropic) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &c.maxAnisotropy);
  c.computeShaders = c.atLeast(4, 3) || epoxy_has_gl_extension("GL_ARB_compute_shader");
  c.directStateAccess = c.atLeast(4, 5) || epoxy_has_gl_extension("GL_ARB_direct_state_access");
  c.timerQuery = c.atLeast(3, 3) || epoxy_has_gl_extension("GL_ARB_timer_query");
  c.softwareRenderer =
      c.renderer.find("llvmpipe") != std::string::npos || c.renderer.find("softpipe") != std::string::npos;
  if (const char* s = std::getenv("SHADOWLAB_SOFTWARE_RENDERER")) c.softwareRenderer = std::string(s) == "1";
  g_caps = c;
  g_detected = true;
  return g_caps;
}

void resetCaps() { g_detected = false; }

std::string Caps::summary() const {
  return renderer + " | GL " + std::to_string(major) + "." + std::to_string(minor) + " (" + version + ")";
}

}  // namespace shadowlab::gl

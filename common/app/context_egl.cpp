// Headless OpenGL through EGL: no window, no display server. Prefers the EGL device platform when
// a GPU driver enumerates devices (real hardware), else Mesa's surfaceless platform (llvmpipe on
// CI). The context renders into an offscreen framebuffer of the requested size.
#include <epoxy/egl.h>

#include <stdexcept>
#include <vector>

#include "app/offscreen_context.hpp"

namespace shadowlab {
namespace {

std::string eglErrorText() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04X", eglGetError());
  return buf;
}

class EglContext final : public OffscreenContext {
 public:
  explicit EglContext(const ContextOptions& o) {
    display_ = openDisplay();
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor))
      throw std::runtime_error("EGL: eglInitialize failed (" + eglErrorText() + ")");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: desktop OpenGL is not available");
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE,
                                    EGL_PBUFFER_BIT,
                                    EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT,
                                    EGL_RED_SIZE,
                                    8,
                                    EGL_GREEN_SIZE,
                                    8,
                                    EGL_BLUE_SIZE,
                                    8,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless contexts need no config on Mesa, but asking for one keeps drivers that require it happy.
    if (!eglChooseConfig(display_, configAttribs, &config, 1, &count) || count == 0) config = EGL_NO_CONFIG_KHR;
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     1,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     o.debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
    if (context_ == EGL_NO_CONTEXT)
      throw std::runtime_error("EGL: no OpenGL 4.1 core context (" + eglErrorText() +
                               "); the course needs 4.1 or newer");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("EGL: eglMakeCurrent without a surface failed (" + eglErrorText() + ")");
    makeFrame(o);
  }
  ~EglContext() override {
    releaseFrame();
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  std::string platform() const override { return platform_; }

 private:
  EGLDisplay openDisplay() {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
      EGLDeviceEXT devices[8];
      EGLint n = 0;
      if (eglQueryDevicesEXT(8, devices, &n)) {
        for (EGLint i = 0; i < n; ++i) {
          // Mesa lists its software rasteriser as a device too; that one goes through surfaceless.
          const char* ext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
          const std::string extensions = ext ? ext : "";
          if (extensions.find("EGL_MESA_device_software") != std::string::npos) continue;
          EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
          EGLint ma, mi;
          if (d != EGL_NO_DISPLAY && eglInitialize(d, &ma, &mi)) {
            platform_ = "EGL device";
            return d;
          }
        }
      }
    }
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY) {
        platform_ = "EGL surfaceless";
        return d;
      }
    }
    throw std::runtime_error(
        "EGL: neither a GPU device (EGL_EXT_platform_device) nor Mesa's surfaceless platform is "
        "available; install libegl-mesa0 (tools/install-deps.sh) or run with a display");
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
};

}  // namespace

std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  return std::make_unique<EglContext>(options);
}

}  // namespace shadowlab

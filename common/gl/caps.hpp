#pragma once
// What the current context can do. OpenGL 4.1 core is the floor; everything newer is used only
// behind one of these flags, with a fallback that works on 4.1 (macOS).
#include <string>

namespace shadowlab::gl {

struct Caps {
  int major = 0, minor = 0;
  std::string vendor, renderer, version, glsl;
  bool khrDebug = false;     // debug callback + object labels (4.3 or GL_KHR_debug)
  bool clipControl = false;  // [0,1] depth (4.5 or GL_ARB_clip_control)
  bool anisotropic = false;  // GL_EXT/ARB_texture_filter_anisotropic
  float maxAnisotropy = 1.0f;
  bool computeShaders = false;  // 4.3 or GL_ARB_compute_shader
  bool directStateAccess = false;
  bool timerQuery = false;  // 3.3 core; still checked (some drivers lie)
  // dFdxFine / dFdyFine in a #version 410 shader (GL_ARB_derivative_control, core in 4.5): a 2x2
  // quad's pixels can share sums (PCSS's quad search, shadow_pcss.frag).
  bool derivativeControl = false;
  bool parallelShaderCompile = false;  // GL_KHR_parallel_shader_compile: programs link on driver threads
  // Mesa's llvmpipe / softpipe (or SHADOWLAB_SOFTWARE_RENDERER=1): the CPU rasterises, deferred, so
  // timestamps miss the work, and an interactive window needs the frame budget.
  bool softwareRenderer = false;
  // OpenGL ES 3.0 through WebGL2 (the browser build): what it lacks is false below, each with the
  // fallback its users take (gl/gles.hpp names every missing call).
  bool gles = false;
  bool depthClamp = false;         // GL_DEPTH_CLAMP (4.1 core; WebGL2: EXT_depth_clamp)
  bool geometryShaders = false;    // 4.1 core; none in WebGL2 (lines and volumes expanded on the CPU)
  bool clampToBorder = false;      // GL_CLAMP_TO_BORDER (4.1; WebGL2: clamp to edge and a range test)
  bool polygonMode = false;        // glPolygonMode wireframe (4.1; WebGL2: WEBGL_polygon_mode)
  bool getTexImage = false;        // glGetTexImage (4.1; WebGL2: read back through a framebuffer)
  bool floatColorBuffers = false;  // render into RGBA32F/RG32F (4.1; WebGL2: EXT_color_buffer_float)
  bool floatLinear = false;        // linear filtering of 32-bit float textures (WebGL2: OES_texture_float_linear)
  bool norm16 = false;             // GL_RGBA16 render targets (4.1 core; WebGL2: EXT_texture_norm16)
  bool clipDistance = false;  // gl_ClipDistance (4.1 core; WebGL2: a varying and discard, SHADOWLAB_NO_CLIP_DISTANCE)
  int maxTextureSize = 0;     // GL_MAX_TEXTURE_SIZE: render targets and textures, a side
  int maxRenderbufferSize = 0;
  int maxViewport[2] = {0, 0};  // GL_MAX_VIEWPORT_DIMS
  bool atLeast(int ma, int mi) const { return major > ma || (major == ma && minor >= mi); }
  std::string summary() const;  // one line for the UI header and logs
};

// Detected once per context (call after the context is current); later calls return the cache.
// SHADOWLAB_GL_HIDE="GL_KHR_debug,GL_ARB_clip_control,..." makes caps() treat those extensions as
// absent, so every fallback can be run on a driver that has them: Mesa cannot switch some of them
// off (MESA_EXTENSION_OVERRIDE keeps KHR_debug), and macOS's 4.1 context has none of them (the gl41
// tests, tests/gl41.cmake).
const Caps& caps();
void resetCaps();  // a new context was created

// "" when a width x height frame fits this context's limits (texture, renderbuffer, viewport),
// else one line naming the size, the limit it passes and the largest size that fits.
std::string framebufferSizeProblem(int width, int height);
// "" when a texture of width x height fits GL_MAX_TEXTURE_SIZE, else one line saying so.
std::string textureSizeProblem(int width, int height);

}  // namespace shadowlab::gl

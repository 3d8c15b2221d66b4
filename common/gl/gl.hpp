#pragma once
// The one place GL comes from: libepoxy resolves entry points for GLX, EGL and WGL contexts alike.
// The browser build (emscripten) gets OpenGL ES 3.0 (WebGL2) from <GLES3/gl3.h>, and the names of
// what ES lacks from gl/gles.hpp: each is used only behind a gl::caps() flag.
#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>

#include "gl/gles.hpp"
#else
#include <epoxy/gl.h>
#endif

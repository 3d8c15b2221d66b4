#pragma once
// The one place GL comes from: libepoxy resolves entry points for GLX, EGL and WGL contexts alike.
#include <epoxy/gl.h>

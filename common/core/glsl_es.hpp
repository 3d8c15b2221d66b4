#pragma once
// The course's GLSL (#version 410 core) as GLSL ES 3.00 (#version 300 es), the browser build's
// shading language (WebGL2). The shaders are written in the common subset of the two, so the
// translation is small and the native path never runs it:
//   - the version line becomes `#version 300 es`;
//   - default precisions follow it (highp for float, int and every sampler type ES leaves without
//     one), and SHADOWLAB_GLES is defined, so a shader can take its ES branch (#ifdef SHADOWLAB_GLES);
//   - #extension lines move up to just after the version line (ES allows them only before any
//     other token); each leaves an empty line behind and a #line directive restores the numbering,
//     so a driver's log still names the right file and line (core/shader_source's mapCompileLog).
// A source without a #version line is refused (std::invalid_argument): the program it came from
// was not expanded by loadShaderSource.
#include <string>

namespace shadowlab {

std::string toGlslEs(const std::string& source);

}  // namespace shadowlab

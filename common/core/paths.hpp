#pragma once
// Where the toolkit finds its data at run time. The source tree is fixed at configure time
// (SHADOWLAB_SOURCE_ROOT), but an installed or relocated copy — or a test — can point elsewhere
// with the SHADOWLAB_ROOT environment variable, which is read on every call so a change takes
// effect without restarting.
#include <string>

namespace shadowlab {

// SHADOWLAB_ROOT if set and non-empty, else the configure-time source tree.
std::string sourceRoot();
// The configure-time source tree, whatever SHADOWLAB_ROOT says (reports name files relative to it).
std::string configuredSourceRoot();
// sourceRoot() + "/shaders": the include directory for every GLSL program.
std::string shaderRoot();
// sourceRoot() + "/textures".
std::string textureRoot();
// A Material::texture as a file: an absolute path (a model's own texture, core/model_file) as it
// is, a name under textureRoot() otherwise.
std::string texturePath(const std::string& name);

}  // namespace shadowlab

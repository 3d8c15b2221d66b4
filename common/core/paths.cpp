#include "core/paths.hpp"

#include <cstdlib>

#ifndef SHADOWLAB_SOURCE_ROOT
#error "SHADOWLAB_SOURCE_ROOT must be defined by the build (see the top-level CMakeLists.txt)"
#endif

namespace shadowlab {

std::string configuredSourceRoot() { return SHADOWLAB_SOURCE_ROOT; }

std::string sourceRoot() {
  // An empty SHADOWLAB_ROOT is treated as unset: "export SHADOWLAB_ROOT=" would otherwise turn
  // every data path into an absolute path under "/".
  const char* env = std::getenv("SHADOWLAB_ROOT");
  std::string root = (env != nullptr && *env != '\0') ? std::string(env) : configuredSourceRoot();
  // Strip trailing slashes so callers can append "/shaders" without producing "//".
  while (root.size() > 1 && root.back() == '/') root.pop_back();
  return root;
}

std::string shaderRoot() { return sourceRoot() + "/shaders"; }

std::string textureRoot() { return sourceRoot() + "/textures"; }

std::string texturePath(const std::string& name) {
  return !name.empty() && name.front() == '/' ? name : textureRoot() + "/" + name;
}

}  // namespace shadowlab

// The browser build's model loading: none (Assimp does not run in the page). --model and a
// dropped file get the one line that says where they work.
#include "core/model_file.hpp"

namespace shadowlab {
namespace {
[[noreturn]] void native(const std::string& name) {
  throw ModelError("model '" + name +
                   "': models load in the native lessons only (make run); the browser has no importer");
}
}  // namespace

ModelFile loadModelFile(const std::string& path) { native(path); }
ModelFile loadModelFromMemory(const void*, std::size_t, const std::string&, const std::string& name) { native(name); }

}  // namespace shadowlab

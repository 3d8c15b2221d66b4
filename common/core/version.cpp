#include "core/version.hpp"
namespace shadowlab {
const char* version() { return "0.1.0"; }
}  // namespace shadowlab

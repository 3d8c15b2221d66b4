#pragma once
namespace shadowlab {
// The toolkit's version, printed by --help and in the UI header.
const char* version();
}  // namespace shadowlab

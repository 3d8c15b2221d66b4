#pragma once
// Shader text that is not a file on disk, found by the #include preprocessor (shader_source.hpp)
// when no real file of that name exists: a real file always wins.
//   - registered text: GLSL a program generates at run time (the GLSL exercise harness);
//   - sealed files: GLSL compiled into the program, obscured (the student handout seals the
//     reference GLSL of its exercises this way; tools/handout/sealed_shaders.txt lists them).
// Keys are paths relative to a shader include directory, e.g. "02_shadow_maps/exercises_reference.glsl".
#include <optional>
#include <string>

namespace shadowlab {

void registerShaderText(const std::string& relativePath, std::string text);
// The registered text for `relativePath`, else the sealed file, else nothing.
std::optional<std::string> virtualShaderText(const std::string& relativePath);

}  // namespace shadowlab

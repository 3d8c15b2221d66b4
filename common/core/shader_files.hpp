#pragma once
// Shader text that is not a file on disk, found by the #include preprocessor (shader_source.hpp)
// when no real file of that name exists: a real file always wins.
//   - registered text: GLSL a program generates at run time (the GLSL exercise harness);
//   - sealed files: GLSL compiled into the program, obscured (the student handout seals the GLSL
//     twins of C++ exercises that later lessons draw with; tools/handout/sealed_shaders.txt).
// A withheld file (an exercise's reference GLSL, which the handout carries in no form) is not
// virtual text: where it is absent, the preprocessor includes its stand-in, the student's
// exercises.glsl beside it, and notes that it did (the lesson's banner says so).
// Keys are paths relative to a shader include directory, e.g. "02_shadow_maps/exercises_reference.glsl".
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

void registerShaderText(const std::string& relativePath, std::string text);
// The registered text for `relativePath`, else the sealed file, else nothing.
std::optional<std::string> virtualShaderText(const std::string& relativePath);

// Whether the handout withholds `relativePath` ("03_shadow_quality/exercises_reference.glsl").
bool shaderWithheld(const std::string& relativePath);
// The stand-in of a withheld file: the exercises.glsl in its folder.
std::string withheldStandIn(const std::string& relativePath);
// The withheld files the preprocessor replaced by their stand-ins so far, in this process, sorted.
void noteWithheldReplaced(const std::string& relativePath);
std::vector<std::string> withheldReplaced();
// The withheld files whose stand-ins a program drawing since the last call was built with (the
// program notes them when it is used: gl::Program::use), sorted; the call starts a new period.
void noteWithheldDrawn(const std::vector<std::string>& relativePaths);
std::vector<std::string> takeWithheldDrawn();

}  // namespace shadowlab

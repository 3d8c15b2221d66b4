#pragma once
// The framework's answers about a lesson before it runs (app.cpp's parse stage).
#include "app/lesson.hpp"
#include "core/cli.hpp"

namespace shadowlab {

// Every hotkey bound to a parameter is a key, unique, and drives a bool, a choice or a number;
// throws ParamError naming each problem.
void checkHotkeys(const ParamRegistry& params);
// --help, --info, --list-params, --list-presets, --list-hotkeys: prints the answer and returns
// true (the run ends with exit code 0); false when the command line asks none of them.
bool answerQuery(const CommandLine& cl, const LessonInfo& info, const ParamRegistry& params, const PresetFile& presets,
                 const Exercises& exercises, const char* program);
// --info: the lesson's number, name, title, summary, difficulty, minutes in class, prerequisites,
// its exercises (id, function, title, glsl, file, line) and the command that grades them, as JSON.
std::string infoJson(const LessonInfo& info, const Exercises& exercises);

}  // namespace shadowlab

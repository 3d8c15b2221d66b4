#pragma once
// The framework's answers about a lesson before it runs (app.cpp's parse stage), and its words
// about what a running lesson shows.
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
// The header's few figures: the lesson's key figures present in `all`, in the lesson's order, then
// (with `measured`) the ground truth's (what M measured).
std::vector<Counter> keyFigures(const LessonInfo& info, const std::vector<Counter>& all, bool measured = true);
// --keys: what a step did, for stderr (tests read it): the camera, and the parameter its key drives.
std::string scriptedKeyReport(const std::string& lesson, const std::string& step, const OrbitCamera& camera, bool fly,
                              const ParamRegistry& params);
// The banner's line when the camera sees none of the lesson's scene (core/camera.hpp's
// sightProblem: behind it, beyond far, nearer than near, off to a side), "" when it may see some;
// "" for a lesson with no scene to measure.
std::string sightBanner(Lesson& lesson, float aspect);

}  // namespace shadowlab
